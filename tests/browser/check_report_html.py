#!/usr/bin/python3
"""Opens DIR/report.html of each run given in headless Chromium and checks it as
a lecture room would meet it: the page loads with no console error and no
request leaving DIR (its images and video are data: URIs), every image is
decoded, the video's metadata plays (a duration), and a screenshot of the
first plot is not blank (the spread of its pixels).

Usage: /usr/bin/python3 check_report_html.py DIR [DIR ...]
Exit 0: passed; 1: failed (the reasons printed); 77: skipped, with the reason
(no chromium, chromedriver, python3-selenium, or matplotlib to draw the plots).
"""
import io
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path

SKIP = 77
BLANK_STD = 5.0  # grey levels: a white or one-colour picture has 0, a plot tens


def skip(reason):
    print(f"skipped: {reason}")
    sys.exit(SKIP)


try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    skip("python3-selenium is not installed (scripts/setup installs it)")
try:
    import matplotlib  # noqa: F401  (the runs' plots need it)
    import numpy as np
    from PIL import Image
except ImportError as exc:
    skip(f"{exc}: the runs have no plots to look at")


def browser(profile):
    chromium, driver = shutil.which("chromium") or shutil.which("chromium-browser"), shutil.which("chromedriver")
    if not chromium or not driver:
        skip("chromium or chromedriver is not installed (scripts/setup installs them)")
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in ["--headless", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--window-size=1440,1000",
                f"--user-data-dir={profile}", "--autoplay-policy=no-user-gesture-required"]:
        options.add_argument(arg)
    if os.geteuid() == 0:
        options.add_argument("--no-sandbox")  # Chromium refuses to run as root inside its sandbox
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(driver), options=options)


def requests(drv):
    """The URL of every request the page made."""
    urls = []
    for entry in drv.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    return urls


def check_page(drv, run_dir):
    problems = []
    page = (run_dir / "report.html").resolve()
    if not page.exists():
        return [f"{page} does not exist"]
    drv.get("about:blank")
    drv.get_log("performance")  # what the browser itself loaded at start (its new-tab page) is not the report's
    drv.get_log("browser")
    drv.get(page.as_uri())
    WebDriverWait(drv, 30).until(lambda d: d.execute_script("return document.readyState") == "complete")
    inside = run_dir.resolve().as_uri() + "/"
    for url in requests(drv):
        if not (url.startswith("data:") or url.startswith(inside)):
            problems.append(f"a request leaves the directory: {url[:120]}")
    for entry in drv.get_log("browser"):
        if entry["level"] == "SEVERE":
            problems.append(f"console error: {entry['message'][:200]}")
    images = drv.execute_script("return Array.from(document.images).map(i => [i.complete, i.naturalWidth, i.alt])")
    if not images:
        problems.append("no image on the page")
    problems += [f"image not decoded: {alt}" for done, width, alt in images if not done or width == 0]
    if drv.find_elements(By.TAG_NAME, "video"):
        duration = drv.execute_async_script(
            "const v = document.querySelector('video'), done = arguments[0];"
            "if (v.readyState >= 1) return done(v.duration);"
            "v.addEventListener('loadedmetadata', () => done(v.duration));"
            "v.addEventListener('error', () => done(-1)); setTimeout(() => done(-2), 20000);")
        if not duration or duration <= 0:
            problems.append(f"the video does not play (duration {duration})")
    problems += check_screenshot(drv)
    rows = len(drv.find_elements(By.CSS_SELECTOR, "table.figures tbody tr"))
    if rows == 0:
        problems.append("no figure of merit on the page")
    print(f"{page}: {len(images)} images, {rows} figures of merit, {len(problems)} problems")
    return problems


def check_screenshot(drv):
    """The first plot, scrolled into view and photographed, is not blank."""
    plots = drv.find_elements(By.CSS_SELECTOR, "#plots ~ figure img")
    if not plots:
        return ["no plot on the page"]
    drv.execute_script("arguments[0].scrollIntoView()", plots[0])
    grey = np.asarray(Image.open(io.BytesIO(plots[0].screenshot_as_png)).convert("L"), dtype=float)
    std, inked = grey.std(), (grey < 200).mean()
    print(f"  screenshot of the first plot: {grey.shape[1]}x{grey.shape[0]}, grey std {std:.1f}, "
          f"{100 * inked:.1f}% inked")
    return [] if std >= BLANK_STD and inked > 0.01 else [f"the plot's screenshot is blank (std {std:.2f})"]


def main():
    dirs = [Path(d) for d in sys.argv[1:]]
    with tempfile.TemporaryDirectory(prefix="shockgas-chromium-") as profile:
        drv = browser(profile)
        try:
            problems = [p for d in dirs for p in check_page(drv, d)]
        finally:
            drv.quit()
    for p in problems:
        print("FAIL", p)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
