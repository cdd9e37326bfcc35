#!/usr/bin/python3
"""Browser test of the study pages (ctest label `browser`, docs/testing.md).

Generates a tiny `pathspace study psf` and a tiny `pathspace study pclt`, opens each study.html from a
file:// URL in headless Debian chromium through selenium, with the network switched off and every
non-file request blocked, and checks what a reader would see: every <img> and every embedded image
(the pages show their PNGs as CSS data-URI backgrounds) decodes with a non-zero size and is laid out
with a non-zero box, every inline <svg> plot has a non-zero size, the page loaded nothing but file:
and data: resources, and the browser console has no errors.

Usage: study_pages_test.py --pathspace BUILD/apps/pathspace/pathspace [--keep DIR]
Exit 0 on success, 1 on a failed check, 77 (ctest: skipped) when chromium, chromedriver or selenium
is missing and PATHSPACE_ALLOW_MISSING_BROWSER=1, else 1 with the missing thing named.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

from browser_support import make_driver

# Small enough for about a minute on 2 cores; every section of both pages still renders.
STUDIES = {
    "psf": ["study", "psf", "--scenes", "bs_c", "--resolution", "24x16", "--time", "0.05", "--reference-time", "0.3",
            "--max-spp", "4", "--vertex-set-resolution", "48x32", "--temporal-frames", "4", "--eviction-frames", "6",
            "--no-exr", "--quiet"],
    "pclt": ["study", "pclt", "--scenes", "bs_c", "--resolution", "24x16", "--time", "0.05", "--reference-time", "0.3",
             "--no-exr", "--quiet"],
}
# Inline SVG plots each page must have (the pclt page has none).
MIN_PLOTS = {"psf": 14, "pclt": 0}

# Collects what the checks need in one round trip; the embedded images are decoded again from their
# data URIs, since a CSS background that fails to decode leaves no trace in the DOM.
PAGE_PROBE = """
const done = arguments[arguments.length - 1];
const box = e => { const r = e.getBoundingClientRect(); return [r.width, r.height]; };
const imgs = Array.from(document.images).map(i => ({src: i.src.slice(0, 80), complete: i.complete,
                                                   natural: [i.naturalWidth, i.naturalHeight], box: box(i)}));
const urls = new Map();
const divs = Array.from(document.querySelectorAll('div.im')).map(d => {
  const m = /url\\("?(.*?)"?\\)$/.exec(getComputedStyle(d).backgroundImage);
  if (m) urls.set(m[1], null);
  return {title: d.title, url: m ? m[1].slice(0, 40) : null, box: box(d)};
});
const svgs = Array.from(document.querySelectorAll('svg')).map(s => ({label: s.getAttribute('aria-label'), box: box(s)}));
const resources = performance.getEntriesByType('resource').map(r => r.name.slice(0, 80));
Promise.all(Array.from(urls.keys()).map(u => new Promise(resolve => {
  const im = new Image();
  im.onload = () => resolve({url: u.slice(0, 40), natural: [im.naturalWidth, im.naturalHeight]});
  im.onerror = () => resolve({url: u.slice(0, 40), natural: [0, 0]});
  im.src = u;
}))).then(decoded => done({imgs, divs, decoded, svgs, resources, url: location.href}));
"""


def make_offline_driver():
    driver = make_driver(window="1400,1000", log_console=True, script_timeout=60)
    # No network: offline, and any request that is not file: or data: is blocked outright.
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions",
                           {"offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    driver.execute_cdp_cmd("Network.setBlockedURLs", {"urls": ["http://*", "https://*", "ws://*", "wss://*", "ftp://*"]})
    return driver


def generate(pathspace, folder, study):
    out = os.path.join(folder, study)
    start = time.monotonic()
    result = subprocess.run([pathspace] + STUDIES[study] + ["-o", out], capture_output=True, text=True)
    if result.returncode != 0:
        print(f"browser test: pathspace study {study} failed ({result.returncode}):\n{result.stderr}")
        sys.exit(1)
    print(f"generated study {study} in {time.monotonic() - start:.1f} s")
    return os.path.join(out, "study.html")


def check_page(driver, study, html):
    failures = []
    driver.get_log("browser")  # drop anything logged before this page
    driver.get("file://" + os.path.abspath(html))
    page = driver.execute_async_script(PAGE_PROBE)
    if not page["url"].startswith("file://"):
        failures.append(f"opened {page['url']}, not a file:// URL")
    for im in page["imgs"]:
        if not im["complete"] or min(im["natural"]) <= 0 or min(im["box"]) <= 0:
            failures.append(f"<img> not displayed: {im}")
    if not page["divs"]:
        failures.append("no embedded images (div.im) on the page")
    for d in page["divs"]:
        if d["url"] is None or not d["url"].startswith("data:image/png"):
            failures.append(f"image without a PNG data URI: {d}")
        if min(d["box"]) <= 0:
            failures.append(f"image laid out with an empty box: {d}")
    for d in page["decoded"]:
        if min(d["natural"]) <= 0:
            failures.append(f"embedded image does not decode: {d['url']}...")
    if len(page["svgs"]) < MIN_PLOTS[study]:
        failures.append(f"{len(page['svgs'])} <svg> plots, expected at least {MIN_PLOTS[study]}")
    for s in page["svgs"]:
        if min(s["box"]) <= 0:
            failures.append(f"<svg> plot with an empty box: {s}")
    for name in page["resources"]:
        if not (name.startswith("file:") or name.startswith("data:")):
            failures.append(f"page requested a network resource: {name}")
    for entry in driver.get_log("browser"):
        if entry.get("level") == "SEVERE":
            failures.append(f"console error: {entry.get('message')}")
    print(f"study {study}: {len(page['imgs'])} <img>, {len(page['divs'])} images ({len(page['decoded'])} distinct), "
          f"{len(page['svgs'])} plots, {len(page['resources'])} resources: {'ok' if not failures else 'FAILED'}")
    return [f"study {study}: {f}" for f in failures]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pathspace", required=True, help="the pathspace binary")
    parser.add_argument("--keep", help="write the studies into this folder and keep them")
    args = parser.parse_args()
    driver = make_offline_driver()
    failures = []
    try:
        with tempfile.TemporaryDirectory(prefix="pathspace-browser-") as tmp:
            folder = args.keep or tmp
            os.makedirs(folder, exist_ok=True)
            for study in STUDIES:
                failures += check_page(driver, study, generate(args.pathspace, folder, study))
    finally:
        driver.quit()
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
