"""Headless Chromium for the browser tests: find it, and load a page in a fresh profile."""
import os
import shutil
import subprocess
import tempfile

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


def write_solution_pages(binary, bank, out, formats):
    """Writes the bank's worked solutions in `formats` ("html,json") to OUT/pages and makes
    OUT/screenshots; returns the two folders."""
    pages = os.path.join(out, "pages")
    shots = os.path.join(out, "screenshots")
    os.makedirs(shots, exist_ok=True)
    subprocess.run([binary, "solutions", bank, "--out", pages, "--format", formats], check=True,
                   capture_output=True)
    return pages, shots
