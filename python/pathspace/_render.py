"""pathspace.render(): one render, returned as numpy arrays, with a progress display and Ctrl-C
that keeps what was rendered."""

from . import _core
from ._options import document


class RenderResult:
    """What a render made.

    image      float32 array (height, width, 3): the mean, linear RGB (what the CLI writes as EXR)
    variance   float32 array (height, width, 3): the variance of that mean, per pixel
    aovs       dict of name -> float32 array: the integrator's and filter's debug images, when asked for
    stats      dict: the content of the CLI's --stats JSON (spp, wall_time_s, rays, statistics, ...)
    options    dict: every option value the render used; render(scene, **options) repeats it
    warnings   list of str: what the scene's validation noticed
    """

    __slots__ = ("image", "variance", "aovs", "stats", "options", "warnings")

    def __init__(self, raw):
        for name in self.__slots__:
            setattr(self, name, raw[name])

    @property
    def spp(self):
        """Samples per pixel (passes) rendered."""
        return self.stats["spp"]

    def __repr__(self):
        height, width = self.image.shape[:2]
        return "<pathspace.RenderResult {}x{}, {} spp, {} {}>".format(
            width, height, self.spp, self.stats["integrator"], self.stats["filter"])


class RenderInterrupted(KeyboardInterrupt):
    """Ctrl-C (KeyboardInterrupt) stopped a render after its current pass. .result holds the
    RenderResult of the passes done (at least one: the pass that was running finishes)."""

    def __init__(self, result):
        super().__init__("render interrupted after {} passes".format(result.spp))
        self.result = result


def _progress_bar():
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None, None
    total = 100.0
    bar = tqdm(total=total, unit="%", desc="pathspace", leave=False,
               bar_format="{desc}: {percentage:3.0f}%|{bar}| {postfix}")

    def update(fraction, stats):
        bar.update(min(total, fraction * total) - bar.n)
        bar.set_postfix_str("{} spp, {:.3g} Mrays/s".format(stats["spp"], stats["mrays_per_s"]), refresh=False)

    return update, bar


@document
def render(scene, integrator="pt", *, spp=None, time=None, filter="none", seed=0, threads=0, device="cpu",
           progress=True, **options):
    """Renders `scene` (a pathspace.Scene) and returns a RenderResult.

    integrator   one of pathspace.integrators(): pt, lt, bpt, sppm, pclt
    spp / time   samples per pixel (default 16, or the scene file's), or seconds of whole passes
    filter       'none' or one of pathspace.filters(), with an integrator that composes with it
    seed         the render is a pure function of the seed, for any thread count
    threads      worker threads, 0: all cores (a process-wide limit while the render runs)
    device       'cpu', or 'cuda' where built and a GPU is present
    progress     True: a tqdm bar when tqdm is installed; a callable: called after every pass as
                 progress(fraction, stats), fraction of spp or of time done; False: nothing

    The GIL is released while rendering, so renders in several threads run at once. Ctrl-C stops
    the render after the pass that is running and raises RenderInterrupted, whose .result holds
    the passes done. Bad options raise TypeError (an unknown keyword, listing the valid ones) or
    ValueError (a bad value, with the CLI's message).
    """
    bar = None
    on_pass = None
    if callable(progress):
        on_pass = progress
    elif progress:
        on_pass, bar = _progress_bar()
    try:
        raw = _core._render(scene, integrator, filter, options, spp, time, seed, threads, device, on_pass)
    finally:
        if bar is not None:
            bar.close()
    result = RenderResult(raw)
    if raw["interrupted"]:
        raise RenderInterrupted(result)
    return result
