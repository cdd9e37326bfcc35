"""What the browser tests share (label `browser`, docs/testing.md): headless Debian chromium through
selenium, and the skip rule when they are missing (exit 77 with PATHSPACE_ALLOW_MISSING_BROWSER=1)."""
import os
import sys

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
SKIP = 77


def missing(what):
    message = f"browser test: {what} is missing (scripts/install-deps installs chromium chromium-driver python3-selenium)"
    if os.environ.get("PATHSPACE_ALLOW_MISSING_BROWSER") == "1":
        print(message + "; skipped (PATHSPACE_ALLOW_MISSING_BROWSER=1)")
        sys.exit(SKIP)
    print(message)
    sys.exit(1)


def make_driver(window="1400,1000", log_console=False, script_timeout=60):
    """A headless chromium driven by selenium; exits through missing() when either is absent."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        missing("python3-selenium")
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.access(path, os.X_OK):
            missing(path)
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", f"--window-size={window}",
                "--no-first-run", "--disable-extensions", "--disable-background-networking", "--disable-sync",
                "--disable-component-update", "--disable-default-apps"):
        options.add_argument(arg)
    if log_console:
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_script_timeout(script_timeout)
    return driver
