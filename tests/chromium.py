"""Headless Chromium for the browser tests: find it, and load a page in a fresh profile."""
import os
import shutil
import subprocess
import tempfile
import time

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def chromium():
    """The path of Debian's chromium, or None when it is not installed."""
    for name in ("chromium", "chromium-browser"):
        path = shutil.which(name)
        if path:
            return path
    return None


# What a browser test returns when there is no browser: ctest's SKIP_RETURN_CODE.
SKIPPED = 77


def require_chromium():
    """The path of chromium, or None after saying how to install it (the test then skips)."""
    browser = chromium()
    if not browser:
        print("chromium is not installed (scripts/install-deps.sh installs it): skipped")
    return browser


def run_browser(browser, args, page):
    """Loads the file `page` with the extra command-line `args` (--dump-dom, --screenshot=...)."""
    with tempfile.TemporaryDirectory(prefix="raygrade-chromium-") as profile:
        cmd = [browser, *FLAGS, f"--user-data-dir={profile}", *args, "file://" + page]
        return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


class PageBrowser:
    """One headless Chromium, driven by Selenium, that loads page after page: the DOM as
    Chromium serialises it after the load (what --dump-dom prints) and screenshots at a given
    window size, without starting a browser for each page. Needs python3-selenium and
    chromedriver (scripts/install-deps.sh's browser extra)."""

    def __enter__(self):
        self._profile = tempfile.TemporaryDirectory(prefix="raygrade-chromium-")
        self.driver = selenium_chromium(self._profile.name)
        return self

    def __exit__(self, *exc):
        try:
            self.driver.quit()
        finally:
            self._profile.cleanup()

    def _load(self, page, size):
        width, height = size
        self.driver.set_window_size(width, height)
        self.driver.get("file://" + page)

    def dom(self, page, size=(1200, 1600)):
        """The page's DOM once loaded, as markup."""
        self._load(page, size)
        return self.driver.execute_script(
            "return new XMLSerializer().serializeToString(document.doctype || '') +"
            " document.documentElement.outerHTML")

    def screenshot(self, page, path, size=(1000, 1600)):
        """A screenshot of the page's window at `size` in the PNG file `path`."""
        self._load(page, size)
        self.driver.execute_script("document.documentElement.style.overflow = 'hidden'")
        self.driver.save_screenshot(path)


def write_solution_pages(binary, bank, out, formats):
    """Writes the bank's worked solutions in `formats` ("html,json") to OUT/pages and makes
    OUT/screenshots; returns the two folders."""
    pages = os.path.join(out, "pages")
    shots = os.path.join(out, "screenshots")
    os.makedirs(shots, exist_ok=True)
    subprocess.run([binary, "solutions", bank, "--out", pages, "--format", formats], check=True,
                   capture_output=True)
    return pages, shots


def selenium_chromium(profile, downloads=None, size="1200,1600"):
    """Headless Chromium driven by Selenium, in the fresh profile folder `profile`; downloads go
    to `downloads` without asking. Needs python3-selenium and chromedriver."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for flag in FLAGS:
        options.add_argument(flag if flag != "--headless" else "--headless=new")
    options.add_argument(f"--user-data-dir={profile}")
    options.add_argument(f"--window-size={size}")
    options.binary_location = chromium()
    if downloads:
        options.add_experimental_option("prefs", {"download.default_directory": downloads,
                                                  "download.prompt_for_download": False})
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    if downloads:
        driver.execute_cdp_cmd("Page.setDownloadBehavior",
                               {"behavior": "allow", "downloadPath": downloads})
    return driver


def click(driver, element):
    """Scrolls an element to the middle of the window, as a person would, and clicks it."""
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", element)
    element.click()


def wait_for_file(folder, name, seconds=30):
    """The path of `name` in `folder` once a download has finished writing it, or None."""
    end = time.time() + seconds
    path = os.path.join(folder, name)
    while time.time() < end:
        if os.path.exists(path) and not os.path.exists(path + ".crdownload"):
            return path
        time.sleep(0.2)
    return None


def wait_for(driver, script, seconds=60):
    """Polls a JavaScript expression until it is truthy; returns its value (None on timeout)."""
    end = time.time() + seconds
    while time.time() < end:
        value = driver.execute_script("return " + script)
        if value:
            return value
        time.sleep(0.05)
    return None
