#!/usr/bin/python3
"""Opens the lab's page (DIR/index.html, written by `shockgas lab --out DIR`) from
file:// in headless Chromium and checks it as an instructor would meet it:

  - it loads with no console error and no request leaving DIR (its worker is a
    blob: made by the page itself);
  - the engine runs: the frame counter advances and the simulated time grows;
  - a setting changed by its slider restarts the run with the new value (the
    page's line of settings says it, the frame counter starts again);
  - bad input (N = 0, r = 1.5, N = 10^9) is refused with a message naming the
    key, and the page goes on (a good value runs again);
  - with --frame-rate: the frames drawn per second of the white-noise scene at N = 2000 and
    N = 10^4, measured over MEASURE_S seconds each, printed
    (docs/performance/lab.md keeps it), and at least MIN_FPS at both unless
    other work holds the cores (load average above BUSY_LOAD per core, which
    the test then says); a measurement, so the default test (lab.page) leaves
    it to lab.page_frame_rate, label slow;
  - a screenshot of the page (DIR/screenshot.png) is not blank.

Usage: /usr/bin/python3 check_lab_page.py DIR [--frame-rate]
Exit 0: passed; 1: failed (the reasons printed); 77: skipped, with the reason.
"""
import io
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

SKIP = 77
MIN_FPS = 30.0  # the lab's promise up to N = 10^4 (docs/gallery.md, "The lab")
MEASURE_S = 4.0
BUSY_LOAD = 1.0  # load average per core above which the frame rate says more about the machine than the page


def skip(reason):
    print(f"skipped: {reason}")
    sys.exit(SKIP)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    skip("python3-selenium is not installed (scripts/setup installs it)")
try:
    import numpy as np
    from PIL import Image
except ImportError as exc:
    skip(f"{exc}: no way to look at the screenshot")


def browser(profile):
    chromium, driver = shutil.which("chromium") or shutil.which("chromium-browser"), shutil.which("chromedriver")
    if not chromium or not driver:
        skip("chromium or chromedriver is not installed (scripts/setup installs them)")
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in ["--headless", "--disable-gpu", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--window-size=1640,1180", f"--user-data-dir={profile}"]:
        options.add_argument(arg)
    if os.geteuid() == 0:
        options.add_argument("--no-sandbox")  # Chromium refuses to run as root inside its sandbox
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(driver), options=options)


def text(drv, element_id):
    return drv.execute_script("return document.getElementById(arguments[0]).textContent", element_id)


def frames(drv):
    return int(text(drv, "frame-count") or 0)


def wait_for(drv, what, condition, seconds=30):
    try:
        WebDriverWait(drv, seconds, poll_frequency=0.1).until(lambda d: condition())
        return []
    except Exception:  # selenium's TimeoutException, or a script error while the page restarts
        return [f"waited {seconds} s in vain for: {what}"]


def set_number(drv, setting, value):
    """Types a value in a setting's box, as a user does: the box's change event."""
    drv.execute_script(
        "const e = document.getElementById(arguments[0] + '-number'); e.value = arguments[1];"
        "e.dispatchEvent(new Event('change'));", setting, str(value))


def play(drv):
    drv.execute_script("if (document.getElementById('play').textContent === 'Play') document.getElementById('play').click()")


def drawn(drv):
    """Frames the page has drawn (a frame the worker sent may be passed over for a newer one)."""
    return int(drv.execute_script("return lab.drawn"))


def frame_rate(drv, scene, n):
    """Frames drawn per second of wall time, the white-noise scene playing at N = n."""
    drv.execute_script("const s = document.getElementById('scene'); s.value = arguments[0];"
                       "s.dispatchEvent(new Event('change'));", scene)
    set_number(drv, "N", n)
    play(drv)
    problems = wait_for(drv, f"a run at N = {n}", lambda: f"N = {n}," in text(drv, "running") and frames(drv) > 5)
    if problems:
        return None, problems
    f0, t0 = drawn(drv), time.monotonic()
    time.sleep(MEASURE_S)
    f1, t1 = drawn(drv), time.monotonic()
    return (f1 - f0) / (t1 - t0), []


def frame_rates(drv):
    """The frame rates at N = 2000 and 10^4, printed; problems if N = 2000 is too slow on a free machine."""
    problems, rates = [], {}
    for n in (2000, 10000):
        rates[n], more = frame_rate(drv, "cooling", n)
        problems += more
    load = os.getloadavg()[0] / (os.cpu_count() or 1)
    print("frame rate, white noise (the gallery's cooling scene: r = 0.97, delta = 0.01, sticky below): " +
          ", ".join(f"N = {n}: {r:.1f} frames/s" for n, r in rates.items() if r is not None) +
          f"; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    slow = {n: r for n, r in rates.items() if r is not None and r < MIN_FPS}
    if slow and load <= BUSY_LOAD:
        problems += [f"{r:.1f} frames/s at N = {n}, fewer than {MIN_FPS}" for n, r in slow.items()]
    elif slow:  # the page's speed is not measured when other processes hold the cores
        print(f"not held against {MIN_FPS} frames/s: the machine is busy (load {load:.1f} per core)")
    return problems


def check(drv, out, measure_frame_rate):
    problems = []
    page = (out / "index.html").resolve()
    if not page.exists():
        return [f"{page} does not exist"]
    drv.get("about:blank")
    drv.get_log("performance")
    drv.get_log("browser")
    drv.get(page.as_uri())
    problems += wait_for(drv, "the frame counter to advance", lambda: frames(drv) >= 20)
    if problems:
        return problems + [f"message: {text(drv, 'message')!r}"]
    t_first = float(text(drv, "sim-time").split()[0])
    problems += wait_for(drv, "the time to grow", lambda: float(text(drv, "sim-time").split()[0]) > t_first)

    # A slider moved: the run restarts with the new value.
    drv.execute_script("const s = document.getElementById('r-slider'); s.value = 0.5;"
                       "s.dispatchEvent(new Event('input')); s.dispatchEvent(new Event('change'));")
    problems += wait_for(drv, "the run to restart with r = 0.5 from the slider",
                         lambda: "r = 0.5," in text(drv, "running") and 0 < frames(drv) < 50)
    play(drv)
    problems += wait_for(drv, "frames at r = 0.5", lambda: frames(drv) > 10)

    # Bad input: refused with a message naming the key, and no hang.
    for setting, value, key in [("N", 0, "initial.N"), ("r", 1.5, "particles.r"), ("N", 10**9, "initial.N")]:
        set_number(drv, setting, value)
        problems += wait_for(drv, f"{setting} = {value} to be refused naming {key}",
                             lambda: key in text(drv, "message") and "error" in
                             drv.execute_script("return document.getElementById('message').className"), 20)
        set_number(drv, setting, 0.5 if setting == "r" else 1000)
        play(drv)
        problems += wait_for(drv, f"the page to run again after {setting} = {value}",
                             lambda: text(drv, "message") == "" and frames(drv) > 5)

    if measure_frame_rate:
        problems += frame_rates(drv)

    # The sine scene past its breaking time, photographed.
    drv.execute_script("const s = document.getElementById('scene'); s.value = 'sine';"
                       "s.dispatchEvent(new Event('change'));")
    play(drv)
    problems += wait_for(drv, "the sine past t = 0.3",
                         lambda: drv.execute_script("return lab.started && lab.scene.name === 'sine' && lab.t > 0.3"), 90)
    drv.execute_script("if (document.getElementById('play').textContent === 'Pause') document.getElementById('play').click()")
    time.sleep(1.0)  # the last frame drawn
    shot = out / "screenshot.png"
    drv.save_screenshot(str(shot))
    grey = np.asarray(Image.open(shot).convert("L"), dtype=float)
    print(f"screenshot {shot}: {grey.shape[1]}x{grey.shape[0]}, grey std {grey.std():.1f}")
    if grey.std() < 5.0:
        problems.append("the screenshot is blank")

    inside = out.resolve().as_uri() + "/"
    for entry in drv.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            url = message["params"]["request"]["url"]
            if not (url.startswith(inside) or url.startswith("blob:") or url.startswith("data:")):
                problems.append(f"a request leaves the directory: {url[:120]}")
    for entry in drv.get_log("browser"):
        if entry["level"] == "SEVERE":
            problems.append(f"console error: {entry['message'][:200]}")
    return problems


def main():
    if len(sys.argv) not in (2, 3) or sys.argv[2:] not in ([], ["--frame-rate"]):
        sys.exit("usage: check_lab_page.py DIR [--frame-rate]")
    out = Path(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="shockgas-chromium-") as profile:
        drv = browser(profile)
        try:
            problems = check(drv, out, sys.argv[2:] == ["--frame-rate"])
        finally:
            drv.quit()
    for p in problems:
        print("FAIL", p)
    print(f"{out / 'index.html'}: {len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
