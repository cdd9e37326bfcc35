"""render()'s keyword arguments, generated from the registry's option catalog (the same table the
CLI builds its options from): their docstring section and the function's signature."""

import inspect

from . import _core


def options(integrator=None, filter=None):
    """The integrator and filter options as dicts (name as a keyword argument, cli name, type,
    default, min/max or choices, help, paper, integrators, filters). With integrator (and filter):
    only the options render() accepts for that combination."""
    out = []
    for o in _core.option_catalog():
        if integrator is not None and integrator not in o["integrators"] and (filter is None or filter not in o["filters"]):
            continue
        o = dict(o)
        o["cli"] = "--" + o["name"]
        o["name"] = o["name"].replace("-", "_")
        o["default"] = _typed_default(o)
        out.append(o)
    return out


def _typed_default(option):
    """The default as a Python value; None where it is not a value ("the scene's" maximum depth):
    None as a keyword argument means the default."""
    text = option["default"]
    if option["type"] == "flag":
        return False
    try:
        if option["type"] == "integer":
            return int(text)
        if option["type"] == "real":
            return float(text)
    except ValueError:
        return None
    return text


def _describe(option):
    kind = option["type"]
    if kind in ("integer", "real"):
        kind += " in [{:g}, {:g}]".format(option["min"], option["max"])
    elif kind == "choice":
        kind = "one of " + ", ".join(repr(c) for c in option["choices"])
    else:
        kind = "bool"
    owners = ["integrator " + i for i in option["integrators"]] + ["filter " + f for f in option["filters"]]
    paper = " [{}]".format(option["paper"]) if option["paper"] else ""
    return "    {} ({}, default {!r}; {}): {}{}".format(
        option["name"], kind, option["default"], ", ".join(owners), option["help"], paper)


def document(function):
    """Appends every option to function's docstring and gives it a signature that lists them."""
    catalog = options()
    lines = ["", "Integrator and filter options (keyword arguments; the CLI's --name-with-dashes):", ""]
    lines += [_describe(o) for o in catalog]
    function.__doc__ = (function.__doc__ or "") + "\n".join(lines) + "\n"
    signature = inspect.signature(function)
    parameters = [p for p in signature.parameters.values() if p.kind != inspect.Parameter.VAR_KEYWORD]
    parameters += [inspect.Parameter(o["name"], inspect.Parameter.KEYWORD_ONLY, default=o["default"]) for o in catalog]
    function.__signature__ = signature.replace(parameters=parameters)
    return function
