#!/usr/bin/env python3
"""A run's report.html in a real browser.

Makes a small run (the demo scene, SVG figures too), then loads its report.html in headless
Chromium (Debian's `chromium`, installed by scripts/setup.sh) and checks that every image
loaded (naturalWidth > 0; the SVG chosen where there is one), that the page logged no console
message and raised no error, that every link and image is relative and names a file of the
folder, and that a screenshot of the page's head (title, status, the run's facts, the table of
error and bias) matches tests/baselines/report_page.png. The values that change from run to run
(version, scene file, wall time, speed, memory) are replaced before the screenshot by the probe
this test adds to a copy of the page; the page itself is not changed.

Usage: check_report.py SEDEM_EXE COMPARE_EXE SOURCE_DIR OUTPUT_DIR. Exit 77 (skipped) when no
chromium is installed.
"""
import html
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse
from pathlib import Path

SKIP = 77

# Added at the top of a copy of the page: records errors and every image's state into the DOM
# (which --dump-dom prints) and fixes the values that differ between runs.
PROBE = r"""<script>
window.__errors = [];
addEventListener('error', e => {
  const t = e.target;
  __errors.push(t && t !== window ? 'failed to load ' + (t.currentSrc || t.src || t.href)
                                  : 'error: ' + e.message);
}, true);
addEventListener('unhandledrejection', e => __errors.push('unhandled rejection: ' + e.reason));
for (const level of ['error', 'warn']) {
  const original = console[level];
  console[level] = (...args) => { __errors.push(level + ': ' + args.join(' ')); original(...args); };
}
addEventListener('DOMContentLoaded', () => {
  for (const id of ['version', 'scene-file', 'wall-time', 'speed', 'memory']) {
    const cell = document.querySelector('#' + id + ' td');
    if (cell) cell.textContent = '(fixed by the test)';
  }
});
addEventListener('load', () => {
  const images = [...document.images].map(i => ({
    src: i.getAttribute('src'), current: i.currentSrc, width: i.naturalWidth,
    complete: i.complete}));
  const figures = document.getElementById('figures');
  const probe = document.createElement('pre');
  probe.id = 'probe';
  probe.hidden = true;
  probe.textContent = JSON.stringify({
    images, errors: __errors,
    head_rows: figures ? Math.floor(figures.getBoundingClientRect().top) : 0});
  document.body.appendChild(probe);
});
</script>
"""

WIDTH, HEIGHT = 1100, 1000


class Links(html.parser.HTMLParser):
    """Every src, srcset and href of a page."""

    def __init__(self):
        super().__init__()
        self.targets = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("src", "href", "srcset") and value is not None:
                self.targets.append((tag, name, value))


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    sedem, compare, source, output = (Path(a).resolve() for a in sys.argv[1:5])
    chromium = os.environ.get("SEDEM_CHROMIUM") or shutil.which("chromium") or shutil.which(
        "chromium-browser")
    if not chromium:
        print("SKIP: no chromium on PATH: this test loads report.html in headless Chromium; "
              "scripts/setup.sh installs Debian's chromium package")
        return SKIP

    started = time.monotonic()
    out = output / "report_page"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    run = out / "demo"
    env = dict(os.environ, SEDEM_GL=os.environ.get("SEDEM_GL", "egl"))
    result = subprocess.run(
        [str(sedem), "run", str(source / "scenes/demo.toml"), "--out", str(run), "--quiet",
         "--set", "output.vector_figures=true", "--set", "integrator.threads=1"],
        env=env, capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        fail("sedem run ended with %d:\n%s%s" % (result.returncode, result.stdout, result.stderr))
    ran = time.monotonic()

    record = json.loads((run / "run.json").read_text())
    if "report.html" not in record["files"]:
        fail("run.json does not list report.html: %s" % record["files"])
    page = (run / "report.html").read_text()

    # Self-contained: every link and image relative, to a file of the folder.
    links = Links()
    links.feed(page)
    for tag, name, value in links.targets:
        url = urllib.parse.urlsplit(value)
        if url.scheme or url.netloc or value.startswith("/"):
            fail("<%s %s=%r> is not a relative link" % (tag, name, value))
        if url.path and not (run / urllib.parse.unquote(url.path)).exists():
            fail("<%s %s=%r> names no file of the run folder" % (tag, name, value))
    if re.search(r"<link\b|@import|url\(", page):
        fail("the page loads a style sheet or a resource from elsewhere")

    # The page as the browser shows it, with the probe (a copy in the same folder, so that its
    # relative links are the page's).
    probe_page = run / "report_probe.html"
    probe_page.write_text(page.replace("<head>", "<head>\n" + PROBE, 1))
    screenshot = out / "report_page_screenshot.png"
    with tempfile.TemporaryDirectory() as profile:
        browser = subprocess.run(
            [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             "--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0",
             "--force-device-scale-factor=1", "--window-size=%d,%d" % (WIDTH, HEIGHT),
             "--screenshot=" + str(screenshot), "--dump-dom", probe_page.as_uri()],
            capture_output=True, text=True, timeout=90)
    browsed = time.monotonic()
    console = [l for l in browser.stderr.splitlines() if ":CONSOLE" in l]
    if console:
        fail("the page logged to the console:\n" + "\n".join(console))
    found = re.search(r'<pre id="probe"[^>]*>(.*?)</pre>', browser.stdout, re.S)
    if browser.returncode != 0 or not found:
        fail("chromium gave no page (status %d):\n%s" % (browser.returncode,
                                                         browser.stderr[-3000:]))
    probe = json.loads(html.unescape(found.group(1)))
    if probe["errors"]:
        fail("errors in the page:\n" + "\n".join(probe["errors"]))

    images = probe["images"]
    figures = sorted(f for f in record["files"] if f.startswith("figures/") and
                     f.endswith(".png"))
    frames = [f for f in record["files"] if f.startswith("frames/column_")]
    if not figures or not frames:
        fail("the demo run wrote no figures or no frames: %s" % record["files"])
    broken = [i for i in images if not i["complete"] or i["width"] <= 0]
    if broken:
        fail("images that did not load: %s" % broken)
    shown = {i["src"] for i in images}
    for f in figures:
        if f not in shown:
            fail("figure %s is not on the page" % f)
        svg = f[:-4] + ".svg"
        if svg in record["files"]:
            current = [i["current"] for i in images if i["src"] == f]
            if not all(c.endswith(svg) for c in current):
                fail("%s has an SVG but the browser showed %s" % (f, current))
    if frames[0] not in shown:
        fail("the first frame %s is not on the page" % frames[0])

    # The head of the page against its baseline.
    rows = probe["head_rows"]
    if not 100 < rows < HEIGHT:
        fail("the figures start at row %d, not within the %d-row screenshot" % (rows, HEIGHT))
    compared = subprocess.run(
        [str(compare), str(screenshot), str(source / "tests/baselines/report_page.png"),
         str(out), str(rows)], capture_output=True, text=True)
    print(compared.stdout + compared.stderr, end="")
    if compared.returncode != 0:
        fail("the screenshot's head differs from the baseline")
    print("report.html: %d images loaded (%d figures, %d frames shown), no console message; "
          "run %.1f s, chromium %.1f s, all %.1f s" %
          (len(images), len(figures), len(frames), ran - started, browsed - ran,
           time.monotonic() - started))
    return 0


if __name__ == "__main__":
    sys.exit(main())
