#!/usr/bin/python3
"""Browser test of `pathspace view` (ctest label `browser`, docs/testing.md, docs/viewer.md).

Starts the viewer on a tiny built-in scene, opens its page in headless Debian chromium through
selenium and checks what a user would see and do: the image appears and changes as passes
accumulate; a key press moves the camera (a new view) and changes the image; malformed, unknown and
out-of-range commands from a second WebSocket get an error each while both clients keep receiving
frames; the server stays healthy after the page closes; bound with --listen, it refuses requests
without its token. A screenshot of each stage is kept in --keep DIR (or a temporary folder).

Usage: viewer_test.py --pathspace BUILD/apps/pathspace/pathspace [--keep DIR]
Exit 0 on success, 1 on a failed check, 77 (ctest: skipped) when chromium, chromedriver or selenium
is missing and PATHSPACE_ALLOW_MISSING_BROWSER=1, else 1 with the missing thing named.
"""
import argparse
import contextlib
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

from browser_support import make_driver
FAILURES = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        FAILURES.append(what)
    return condition


def start_viewer(pathspace, extra, resolution="64x48", scene="cornell-box"):
    """The viewer process and the URL it printed."""
    proc = subprocess.Popen([pathspace, "view", scene, "-r", resolution, "-j", "1"] + extra, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    line = proc.stdout.readline()
    match = re.search(r"open (http://\S+)", line)
    if not match:
        proc.kill()
        print("the viewer printed no URL: " + line + proc.stdout.read())
        sys.exit(1)
    return proc, match.group(1)


@contextlib.contextmanager
def viewer_page(pathspace, extra, **viewer_args):
    """A viewer (start_viewer's arguments) with a browser on its page; both end afterwards."""
    proc, url = start_viewer(pathspace, extra, **viewer_args)
    driver = make_driver(window="800,600", script_timeout=30)
    try:
        driver.get(url)
        yield driver
    finally:
        driver.quit()
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=30)


def http_status(url):
    try:
        with urllib.request.urlopen(url, timeout=10) as r:
            return r.status
    except urllib.error.HTTPError as e:
        return e.code


def wait_for(driver, script, timeout=30.0):
    """Polls a JavaScript expression until it is truthy; its last value."""
    end = time.monotonic() + timeout
    value = None
    while time.monotonic() < end:
        value = driver.execute_script("return " + script)
        if value:
            return value
        time.sleep(0.1)
    return value


# The PNG on screen as a data URL, to tell frames apart (frames counts decoded images only).
PIXELS = """
const img = document.getElementById('frame');
if (!img.complete || img.naturalWidth === 0) return 'not decoded';
const c = document.createElement('canvas');
c.width = img.naturalWidth; c.height = img.naturalHeight;
c.getContext('2d').drawImage(img, 0, 0);
return c.toDataURL();
"""

# A second client: each message in arguments[1] is sent and answered in order; a frame request is
# answered by a text (statistics) and a binary message (the PNG).
SECOND_CLIENT = """
const done = arguments[arguments.length - 1];
const messages = arguments[0];
const ws = new WebSocket('ws://' + location.host + '/ws' + location.search);
ws.binaryType = 'arraybuffer';
const answers = [];
ws.onopen = () => { for (const m of messages) ws.send(m); };
ws.onmessage = e => {
  answers.push(typeof e.data === 'string' ? e.data : 'binary ' + e.data.byteLength);
  if (answers.length === messages.length + 1) { ws.close(); done(answers); }
};
ws.onerror = () => done(answers.concat(['socket error']));
setTimeout(() => done(answers.concat(['timeout'])), 20000);
"""


# A client whose frame request waits (the viewer idles after --max-spp), then a camera move: the
# move must be read at once, not after a frame that never comes, and its view must arrive, first as
# a preview. Returns the (view, preview) of the frames received within 3 s of the move.
PENDING_FRAME = """
const done = arguments[arguments.length - 1];
const ws = new WebSocket('ws://' + location.host + '/ws' + location.search);
ws.binaryType = 'arraybuffer';
const seen = [];
let moved = false;
ws.onopen = () => ws.send('{"cmd":"frame"}');
ws.onmessage = e => {
  if (typeof e.data === 'string') {
    const m = JSON.parse(e.data);
    if (m.stats && moved) seen.push([m.stats.view, m.stats.preview]);
    return;
  }
  ws.send('{"cmd":"frame"}');
  if (!moved) setTimeout(() => { moved = true; ws.send('{"cmd":"move","forward":1}'); setTimeout(() => { ws.close(); done(seen); }, 3000); }, 500);
};
ws.onerror = () => done(['socket error']);
setTimeout(() => done(seen.concat(['timeout'])), 20000);
"""


def error_text(driver):
    return driver.execute_script("return document.getElementById('error').textContent")


def pixels(driver):
    """The decoded frame on screen (waits while a new one is loading)."""
    for _ in range(300):
        value = driver.execute_script(PIXELS)
        if value != "not decoded":
            return value
        time.sleep(0.01)
    return "not decoded"


def changed_from(driver, before, timeout=30.0):
    """Waits for a decoded frame that differs from `before`; whether one came."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        now = pixels(driver)
        if now != before and now != "not decoded":
            return now
        time.sleep(0.05)
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--pathspace", required=True)
    parser.add_argument("--keep", help="keep the screenshots in this folder")
    args = parser.parse_args()
    shots = args.keep or tempfile.mkdtemp(prefix="pathspace-viewer-")
    os.makedirs(shots, exist_ok=True)
    driver = make_driver(window="800,600", script_timeout=30)
    out_dir = tempfile.mkdtemp(prefix="pathspace-viewer-out-")
    viewer, url = start_viewer(args.pathspace, ["--out-dir", out_dir])
    try:
        driver.get(url)
        check(wait_for(driver, "Number(document.getElementById('frame').dataset.frames || 0) >= 3"), "the page shows frames")
        check(wait_for(driver, "document.getElementById('frame').naturalWidth === 64"), "the frame is 64 pixels wide")
        first = pixels(driver)
        check(wait_for(driver, "document.getElementById('status').textContent.includes('spp')"), "the statistics show")
        later = changed_from(driver, first)
        check(later is not None, "the image changes as passes accumulate")
        driver.save_screenshot(os.path.join(shots, "viewer-accumulating.png"))
        driver.find_element("id", "save").click()
        saved = wait_for(driver, "document.getElementById('saved').textContent")
        files = sorted(f for f in os.listdir(out_dir) if "-view" in f)
        check(len(files) == 2 and files[0].endswith(".exr") and files[1].endswith(".png") and files[0].startswith("cornell-box-view0-"),
              f"Save writes the frame as EXR and PNG: {saved} -> {files}")

        from selenium.webdriver.common.action_chains import ActionChains

        cli_before = driver.execute_script("return document.getElementById('cli').value")
        ActionChains(driver).send_keys("w").perform()
        check(wait_for(driver, "document.getElementById('status').textContent.includes('view 1,')"), "a key press starts a new view")
        check(changed_from(driver, later) is not None, "the moved camera changes the image")
        cli = driver.execute_script("return document.getElementById('cli').value")
        check("--camera-pos" in cli and "--fov" in cli, "the page offers the view's CLI options: " + cli)
        check(cli != cli_before, "the key moved the camera (its --camera-pos changed)")
        driver.save_screenshot(os.path.join(shots, "viewer-moved.png"))
        driver.find_element("id", "record").click()
        check(wait_for(driver, "document.getElementById('saved').textContent.startsWith('recording')"), "Record starts a flight")
        for key in "dd":
            ActionChains(driver).send_keys(key).perform()
            time.sleep(0.3)
        frames = driver.execute_script("return Number(document.getElementById('frame').dataset.frames)")
        wait_for(driver, f"Number(document.getElementById('frame').dataset.frames) > {frames + 3}")
        driver.find_element("id", "record").click()
        recorded = wait_for(driver, "document.getElementById('saved').textContent.startsWith('recorded') && "
                                    "document.getElementById('saved').textContent")
        pngs = [f for f in os.listdir(out_dir) if "-flight-1-" in f and f.endswith(".png")]
        check(len(pngs) >= 3, f"the flight's frames are written: {recorded} ({len(pngs)} PNG files)")
        check(os.path.exists(os.path.join(out_dir, "cornell-box-flight-1.mp4")) == os.access("/usr/bin/ffmpeg", os.X_OK),
              "the flight's video is encoded where ffmpeg is")

        check(wait_for(driver, "document.getElementById('opt-max-depth') !== null"), "the page lists the integrator's options")
        depth = driver.find_element("id", "opt-max-depth")
        depth.send_keys("abc\n")
        check(wait_for(driver, "document.getElementById('error').textContent.includes('max-depth')"),
              "a bad option value shows the CLI's error: " + driver.execute_script("return document.getElementById('error').textContent"))
        frames = driver.execute_script("return Number(document.getElementById('frame').dataset.frames)")
        check(wait_for(driver, f"Number(document.getElementById('frame').dataset.frames) > {frames + 2}"),
              "the render goes on after the bad value")
        from selenium.webdriver.support.ui import Select
        Select(driver.find_element("id", "opt-filter")).select_by_value("hashed")
        check(wait_for(driver, "document.getElementById('status').textContent.includes('pt + hashed')"),
              "choosing the hashed filter takes effect")
        check(wait_for(driver, "document.getElementById('details').textContent.includes('hashed.')"),
              "the statistics show the filter's counters")
        check(wait_for(driver, "document.getElementById('opt-psf-voxel-size') !== null || "
                               "document.querySelectorAll('#options tr').length > 10"), "the filter's options are listed")
        # The device: without a usable GPU the session cannot be made; the page shows why and the
        # render goes on with the options before (on a GPU machine the render moves to it).
        Select(driver.find_element("id", "opt-device")).select_by_value("cuda")
        outcome = wait_for(driver, "(/cuda|CUDA|GPU/.test(document.getElementById('error').textContent) && "
                                   "document.getElementById('opt-device').value === 'cpu' && 'refused') || "
                                   "(document.getElementById('details').textContent.includes('\"cuda\"') && 'moved')")
        check(outcome in ("refused", "moved"), f"choosing --device cuda moves the render or says why not: {outcome}, "
              + error_text(driver))
        if outcome == "moved":
            Select(driver.find_element("id", "opt-device")).select_by_value("cpu")
        frames = driver.execute_script("return Number(document.getElementById('frame').dataset.frames)")
        check(wait_for(driver, f"Number(document.getElementById('frame').dataset.frames) > {frames + 2}"),
              "the render goes on after the device choice")
        driver.save_screenshot(os.path.join(shots, "viewer-options.png"))
        driver.find_element("id", "opt-aov").click()
        check(wait_for(driver, "Array.from(document.getElementById('show').options).some(o => o.value === 'voxel')"),
              "the filter's debug images can be shown")
        before = pixels(driver)
        Select(driver.find_element("id", "show")).select_by_value("voxel")
        check(wait_for(driver, "document.getElementById('show').value === 'voxel' && "
                               "document.getElementById('status').textContent.includes('spp')"), "the voxel view is chosen")
        check(changed_from(driver, before) is not None, "the voxel view shows another image")
        driver.save_screenshot(os.path.join(shots, "viewer-debug-voxel.png"))
        Select(driver.find_element("id", "show")).select_by_value("image")
        before = pixels(driver)
        Select(driver.find_element("id", "tonemap")).select_by_value("aces")
        check(changed_from(driver, before) is not None, "the ACES tone curve changes the image shown")
        Select(driver.find_element("id", "tonemap")).select_by_value("clip")
        Select(driver.find_element("id", "split")).select_by_value("filter:none")
        check(wait_for(driver, "document.getElementById('status').textContent.includes('right half: pt, filter none')"),
              "the split screen shows the unfiltered render beside the filtered one")
        driver.save_screenshot(os.path.join(shots, "viewer-split.png"))
        Select(driver.find_element("id", "split")).select_by_value("integrator:bpt")
        check(wait_for(driver, "document.getElementById('status').textContent.includes('right half: bpt, filter none')"),
              "the split screen shows another integrator beside the view's")
        image = driver.find_element("id", "frame")
        width = image.size["width"]
        ActionChains(driver).move_to_element_with_offset(image, width // 4, 0).click().perform()
        inspected = wait_for(driver, "document.getElementById('pixel').textContent.includes('right half') && "
                                     "document.getElementById('pixel').textContent")
        check(inspected and "paths" in str(inspected), f"a click on the right half inspects the other integrator's pixel: {inspected}")
        driver.save_screenshot(os.path.join(shots, "viewer-split-integrators.png"))
        Select(driver.find_element("id", "split")).select_by_value("off")
        ActionChains(driver).move_to_element_with_offset(image, -width // 4, 0).click().perform()
        inspected = wait_for(driver, "!document.getElementById('pixel').textContent.includes('half') && "
                                     "document.getElementById('pixel').textContent")
        check(inspected and re.search(r"pixel \(1[56], \d+\): .* ± .*, \d+ paths", str(inspected)),
              f"a click inspects the pixel under the pointer: {inspected} (error: {error_text(driver)})")

        check(driver.execute_script("return document.getElementById('animation').hidden"), "a still scene has no play controls")
        bad = ['{"cmd":"move","forward":"x"}', '{"cmd":"nope"}', 'not json', '{"cmd":"turn","yaw":1e9}',
               '{"cmd":"move","sideways":1}', '{"cmd":"play","on":true}', '{"cmd":"frame"}']
        answers = driver.execute_async_script(SECOND_CLIENT, bad)
        print("second client:", answers)
        check(len(answers) == 8, "the second client is answered every message")
        errors = [a for a in answers[:6] if '"error"' in a]
        check(len(errors) == 6, "each bad command gets an error")
        check(any("must be a number" in a for a in errors) and any("unknown command" in a for a in errors)
              and any("within" in a for a in errors) and any("unknown field" in a for a in errors)
              and any("no animation" in a for a in errors), "the errors say what is wrong")
        check(len(answers) == 8 and '"stats"' in answers[6] and answers[7].startswith("binary "),
              "two clients at once: the second receives a frame too")
        frames = driver.execute_script("return Number(document.getElementById('frame').dataset.frames)")
        check(wait_for(driver, f"Number(document.getElementById('frame').dataset.frames) > {frames}"),
              "the page keeps receiving frames after the bad commands")
        driver.save_screenshot(os.path.join(shots, "viewer-after-errors.png"))
        driver.get("about:blank")
        check(http_status(url) == 200, "the server is healthy after the page closed")
    finally:
        driver.quit()
        viewer.send_signal(signal.SIGTERM)
        code = viewer.wait(timeout=30)
    check(code == 128 + signal.SIGTERM, f"SIGTERM ends the viewer with 143 (got {code})")

    # --reference: live metrics, their plot and the error map; a reference of another size is refused.
    reference = os.path.join(out_dir, "reference.exr")
    subprocess.run([args.pathspace, "render", "cornell-box", "-r", "64x48", "-s", "64", "-q", "-o", reference], check=True)
    small = subprocess.run([args.pathspace, "view", "cornell-box", "-r", "32x24", "--reference", reference], capture_output=True, text=True)
    check(small.returncode == 2 and "64x48" in small.stderr, "a reference of another size is a usage error: " + small.stderr.strip())
    with viewer_page(args.pathspace, ["--reference", reference]) as driver:
        check(wait_for(driver, "document.getElementById('metrics').textContent.includes('relMSE')"), "the metrics show: " +
              str(driver.execute_script("return document.getElementById('metrics').textContent")))
        check(wait_for(driver, "!document.getElementById('plot').hidden"), "the metrics are plotted")
        check(wait_for(driver, "Array.from(document.getElementById('show').options).some(o => o.value === 'error')"),
              "the error map can be shown")
        image = driver.find_element("id", "frame")
        ActionChains(driver).move_to_element_with_offset(image, 0, 0).click().perform()
        inspected = wait_for(driver, "document.getElementById('pixel').textContent.includes('reference') && "
                                     "document.getElementById('pixel').textContent")
        check(inspected and "luminance error" in str(inspected),
              f"the inspector shows the reference's pixel: {inspected} (error: {error_text(driver)})")
        driver.save_screenshot(os.path.join(shots, "viewer-reference.png"))

    # A move while a frame request waits, at a size where a pass takes far longer than its preview.
    with viewer_page(args.pathspace, ["--filter", "hashed", "--max-spp", "2"], resolution="640x360") as driver:
        check(wait_for(driver, "document.getElementById('status').textContent.includes('2 spp')"), "the viewer idles at --max-spp")
        seen = driver.execute_async_script(PENDING_FRAME)
        print("frames after the move:", seen)
        check(len(seen) >= 2 and seen[0] == [1, 2], "a move is read while a frame request waits, and answered by a preview first")
        check([1, 1] in seen, "the full view follows its preview")

    # An animated scene: Play advances its time frame by frame, Pause stops it, a time seeks.
    with viewer_page(args.pathspace, ["--filter", "hashed", "--temporal", "integrate"], scene="cornell-moving-light") as driver:
        check(wait_for(driver, "!document.getElementById('animation').hidden"), "an animated scene shows its play controls")
        before = pixels(driver)
        driver.find_element("id", "play").click()
        check(wait_for(driver, "/t (0\\.[1-9]|[1-9])/.test(document.getElementById('status').textContent)"),
              "Play advances the animation's time: " + driver.execute_script("return document.getElementById('status').textContent"))
        check(changed_from(driver, before) is not None, "the light moves in the image")
        driver.find_element("id", "play").click()
        check(wait_for(driver, "document.getElementById('play').textContent === 'Play'"), "Pause stops it")
        driver.execute_script("const t = document.getElementById('time'); t.value = '2'; t.dispatchEvent(new Event('change'));")
        check(wait_for(driver, "document.getElementById('status').textContent.includes('t 2.00 s')"), "a time seeks the animation")
        driver.save_screenshot(os.path.join(shots, "viewer-animation.png"))

    guarded, guarded_url = start_viewer(args.pathspace, ["--listen", "127.0.0.1"])
    try:
        check("token=" in guarded_url, "--listen prints a URL with a token")
        plain = re.sub(r"\?token=.*", "", guarded_url)
        check(http_status(plain) == 403, "without the token the page is refused")
        check(http_status(guarded_url) == 200, "with the token the page is served")
    finally:
        guarded.send_signal(signal.SIGTERM)
        guarded.wait(timeout=30)
    print(f"screenshots in {shots}")
    if FAILURES:
        print(f"{len(FAILURES)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
