#!/usr/bin/env python3
"""Every figure of a run, as PNG, SVG and PDF, shows the same picture wherever a reader opens it.

Makes a run of the paper's sample 5 (3000 particles, the whole 24 h test: every figure has
data) with `output.figure_formats = png,svg,pdf`, then renders each figure's SVG with
rsvg-convert (librsvg, as GNOME, Inkscape's import and many converters draw it) and in headless
Chromium (as a browser and report.html show it), and its PDF with pdftoppm (poppler, as most PDF
viewers draw it), each at the PNG's size, and compares each picture with the PNG:

- the data pixels: every coloured pixel of the PNG (curves, markers, bands) has a coloured
  (or faintly coloured) pixel within 2 pixels in the other picture and the other way round,
  and the same for dark pixels (black curves, axes, text, Fig. 11's bands and grains), to
  95 %: an SVG whose curves are clipped away or smeared, or text that lands elsewhere, fails;
- the whole picture: the mean difference of the grey levels stays within a few levels
  (anti-aliasing and font hinting differ between renderers, nothing else may).

Usage: check_figure_formats.py SEDEM_EXE SOURCE_DIR OUTPUT_DIR. Exit 77 (skipped) when a
renderer is not installed (scripts/setup.sh installs them with the test tools).
"""
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

SKIP = 77
WIDTH = 800  # the figures' PNG width in this test: small enough to be quick
# The share of one picture's data pixels the other must have nearby, and the largest mean
# grey difference (of 255).
MATCHED = 0.95
MEAN_GREY = 8.0


def fail(message):
    print("check_figure_formats: " + message, file=sys.stderr)
    sys.exit(1)


def read_png(path):
    """The picture as an H x W x 3 float array, top row first, alpha laid on white."""
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        fail("cannot read %s" % path)
    a = vtk_to_numpy(scalars).reshape(h, w, -1)[::-1].astype(float)
    if a.shape[2] in (2, 4):
        alpha = a[:, :, -1:] / 255.0
        a = a[:, :, :-1] * alpha + 255.0 * (1 - alpha)
    if a.shape[2] == 1:
        a = np.repeat(a, 3, axis=2)
    return a[:, :, :3]


def near(mask, reach=2):
    """The mask grown by `reach` pixels in every direction."""
    grown = mask.copy()
    h, w = mask.shape
    for dy in range(-reach, reach + 1):
        for dx in range(-reach, reach + 1):
            shifted = np.zeros_like(mask)
            shifted[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)] = \
                mask[max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)]
            grown |= shifted
    return grown


def masks(picture, loose=False):
    """Coloured and dark pixels; `loose` takes fainter ones too, as a thin line one renderer
    draws crisp another spreads over two rows of lighter pixels. Each loose class holds the
    strict one: a dark pixel faintly tinted (a dark curve over a translucent band) stays dark."""
    spread = picture.max(axis=2) - picture.min(axis=2)
    colour = spread > (25 if loose else 60)
    dark = (picture.mean(axis=2) < (200 if loose else 110)) & ~(spread > 60)
    return {"coloured": colour, "dark": dark}


def compare(reference, other, what):
    """Problems of `other` against the PNG `reference`, as messages."""
    if reference.shape != other.shape:
        return ["%s is %dx%d, the PNG %dx%d" % (what, other.shape[1], other.shape[0],
                                                reference.shape[1], reference.shape[0])]
    problems = []
    ref_masks, other_masks = masks(reference), masks(other)
    ref_loose, other_loose = masks(reference, True), masks(other, True)
    for kind in ref_masks:
        a, b = ref_masks[kind], other_masks[kind]
        if a.sum() < 20 and b.sum() < 20:
            continue
        found = (a & near(other_loose[kind])).sum() / max(a.sum(), 1)
        extra = (b & near(ref_loose[kind])).sum() / max(b.sum(), 1)
        if found < MATCHED or extra < MATCHED:
            problems.append("%s: %.1f %% of the PNG's %s pixels (%d) have one nearby, "
                            "%.1f %% of its own (%d) have one in the PNG" %
                            (what, 100 * found, kind, a.sum(), 100 * extra, b.sum()))
    grey = np.abs(reference.mean(axis=2) - other.mean(axis=2)).mean()
    if grey > MEAN_GREY:
        problems.append("%s: mean grey difference %.2f > %.1f" % (what, grey, MEAN_GREY))
    print("  %-28s grey difference %.2f" % (what, grey))
    return problems


def main():
    if len(sys.argv) != 4:
        fail("usage: check_figure_formats.py SEDEM_EXE SOURCE_DIR OUTPUT_DIR")
    sedem, source, output = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    tools = {name: shutil.which(name) for name in ("rsvg-convert", "pdftoppm", "chromium")}
    missing = [name for name, path in tools.items() if not path]
    if missing:
        print("check_figure_formats: skipped, not installed: %s (scripts/setup.sh installs "
              "them)" % ", ".join(missing))
        sys.exit(SKIP)

    out = output / "figure_formats"
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    run = out / "run"
    made = subprocess.run(
        [str(sedem), "run", str(source / "scenes" / "sample5.toml"), "--out", str(run), "--quiet",
         "--set", "sample.simulated_count=3000", "--set", "output.figure_formats=png,svg,pdf",
         "--set", "output.figure_width_px=%d" % WIDTH, "--set", "integrator.threads=1"],
        capture_output=True, text=True, timeout=300)
    if made.returncode != 0:
        fail("the sample-5 run failed (%d):\n%s" % (made.returncode, made.stderr[-3000:]))

    figures = sorted(p.with_suffix("") for p in (run / "figures").glob("*.png"))
    if len(figures) != 8:
        fail("the sample-5 run wrote %d figures, not Figs. 11-18: %s" % (len(figures), figures))
    pngs = {}
    for base in figures:
        for ext in (".svg", ".pdf", ".csv"):
            if not base.with_suffix(ext).exists():
                fail("%s has no %s" % (base.name, ext))
        pngs[base] = read_png(base.with_suffix(".png"))
        if pngs[base].shape[1] != WIDTH:
            fail("%s.png is %d pixels wide, asked %d" % (base.name, pngs[base].shape[1], WIDTH))

    # Chromium: every SVG in one page, one below the other at its PNG's size, one screenshot.
    page = out / "svgs.html"
    rows = "".join('<img src="%s" style="display:block;width:%dpx;height:%dpx">' %
                   (base.with_suffix(".svg").as_uri(), p.shape[1], p.shape[0])
                   for base, p in pngs.items())
    page.write_text('<!DOCTYPE html><html><body style="margin:0;background:#fff">%s</body>'
                    '</html>' % rows)
    total = sum(p.shape[0] for p in pngs.values())
    shot = out / "chromium.png"
    with tempfile.TemporaryDirectory() as profile:
        browser = subprocess.run(
            [tools["chromium"], "--headless=new", "--no-sandbox", "--disable-gpu",
             "--hide-scrollbars", "--user-data-dir=" + profile, "--force-device-scale-factor=1",
             "--allow-file-access-from-files", "--window-size=%d,%d" % (WIDTH, total),
             "--screenshot=" + str(shot), page.as_uri()],
            capture_output=True, text=True, timeout=120)
    if browser.returncode != 0 or not shot.exists():
        fail("chromium gave no screenshot (%d):\n%s" % (browser.returncode,
                                                        browser.stderr[-3000:]))
    screenshot = read_png(shot)

    problems = []
    top = 0
    for base, png in pngs.items():
        h, w = png.shape[:2]
        print(base.name)
        svg_png = out / (base.name + ".rsvg.png")
        subprocess.run([tools["rsvg-convert"], "-w", str(w), "-h", str(h), "-b", "white",
                        "-o", str(svg_png), str(base.with_suffix(".svg"))], check=True)
        problems += compare(png, read_png(svg_png), base.name + ".svg (rsvg-convert)")
        problems += compare(png, screenshot[top:top + h], base.name + ".svg (Chromium)")
        top += h
        pdf_png = out / (base.name + ".pdftoppm")
        subprocess.run([tools["pdftoppm"], "-png", "-singlefile", "-scale-to-x", str(w),
                        "-scale-to-y", str(h), str(base.with_suffix(".pdf")), str(pdf_png)],
                       check=True)
        problems += compare(png, read_png(str(pdf_png) + ".png"), base.name + ".pdf (pdftoppm)")
    if problems:
        fail("figures that differ between formats (pictures in %s):\n  %s" %
             (out, "\n  ".join(problems)))
    print("check_figure_formats: %d figures agree as PNG, SVG (rsvg-convert, Chromium) and PDF"
          % len(pngs))


if __name__ == "__main__":
    main()
