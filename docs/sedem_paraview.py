# Opens a sedem run in ParaView the way the paper shows it, and can save that as a state file.
#
#   sedem paraview RUN_DIR                        (runs this with pvpython: writes RUN_DIR/sedem.pvsm)
#   pvpython sedem_paraview.py RUN_DIR [--time T] [--screenshot FILE.png] [--state FILE.pvsm]
#   paraview --script=sedem_paraview.py           (RUN_DIR from SEDEM_RUN, or the current folder)
#
# `cmake --install` puts it where ParaView looks for macros (see docs/paraview.md): Macros >
# sedem_paraview then runs it from the toolbar, on SEDEM_RUN or the folder ParaView started in.
#
# Three views, all on the same time (play the VCR controls and they move together):
#   - the column, the section face on: the layers' suspension density as a strip coloured over
#     the suspension's own range (the bed, which is far denser, drawn apart in brown), at most
#     COLUMN_GRAINS grains as dots coloured by diameter and sized by it (not to scale: at the
#     column's scale a 70 um grain is a tenth of a pixel), the hydrometer's bulb;
#   - a zoom where the grains are (the bed's surface, else the largest grains), small enough
#     that the median grain is ZOOM_DISC_PX pixels across: each grain a disc at its true
#     diameter, coloured by diameter, with a dot at its centre; a red frame in the column
#     shows where it is;
#   - the suspension density against depth, over the same range: each layer, and their mean
#     over a hundredth of the column.
# --screenshot writes the three views as one PNG; --state saves a ParaView state file.
import builtins  # ParaView's Python filters put numpy's max, min, abs in __main__
import math
import os
import sys

import numpy as np
import paraview.simple

from paraview.simple import (
    AssignViewToLayout, Box, Calculator, ColorBy, CreateLayout, CreateView, GetAnimationScene,
    GetColorTransferFunction, GetScalarBar, GetTimeKeeper, MaskPoints, ProgrammableFilter,
    PVDReader, Render, SaveScreenshot, SaveState, Show, Text, Threshold, Transform, servermanager)

WIDTH, HEIGHT_PX = 1600, 900  # the layout, pixels
COLUMN_GRAINS = 3000  # at most this many grains drawn in the column view
ZOOM_GRAINS = 40  # the zoom window holds about this many grains
ZOOM_DISC_PX = 8  # and draws their median grain at least this many pixels across
SMOOTH = 0.01  # the strip's running mean, as a fraction of the column's height
BED_COLOUR = [0.55, 0.38, 0.2]
ZOOM_COLOUR = [0.85, 0.1, 0.1]

# Adds `suspension_density_mean`: each layer's suspension density averaged with its
# neighbours over SMOOTH of the column (the bed's layers left out of the mean and kept as they
# are). One layer of 4000 holds a few simulated grains: its density is noisy, the mean is not.
MEAN_SCRIPT = """
import numpy as np
from vtkmodules.numpy_interface import dataset_adapter as dsa
source = dsa.WrapDataObject(self.GetInputDataObject(0, 0))
output = self.GetOutputDataObject(0)
output.ShallowCopy(source.VTKObject)
rho = np.asarray(source.PointData["suspension_density"])[0::2]
bed = np.asarray(source.PointData["bed"])[0::2] > 0
window = int(round(%r * len(rho))) or 1  # (max is numpy's here)
kernel = np.ones(window)
fluid = (~bed).astype(float)
total = np.convolve(np.where(bed, 0.0, rho), kernel, mode="same")
count = np.convolve(fluid, kernel, mode="same")
mean = np.where(bed | (count == 0), rho, total / np.maximum(count, 1.0))
dsa.WrapDataObject(output).PointData.append(np.repeat(mean, 2), "suspension_density_mean")
""" % SMOOTH


def arguments(argv):
    run, time, screenshot, state = None, None, None, None
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--time", "--screenshot", "--state") and i + 1 < len(argv):
            value = argv[i + 1]
            i += 2
            if a == "--time":
                time = float(value)
            elif a == "--screenshot":
                screenshot = value
            else:
                state = value
            continue
        run = a
        i += 1
    if run is None:
        run = os.environ.get("SEDEM_RUN", os.getcwd())
    return os.path.abspath(run), time, screenshot, state


def open_series(run, name):
    path = os.path.join(run, name + ".pvd")
    if not os.path.exists(path):
        return None
    return PVDReader(registrationName=name + ".pvd", FileName=path)


def black_text(bar, title):
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 15
    bar.LabelFontSize = 13
    bar.ScalarBarLength = 0.3
    bar.AddRangeLabels = 1


def white_render_view(size):
    view = CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.ViewSize = size
    return view


def discs(source, view, scale, through_function):
    """The grains as flat discs of `scale` times their radius (through the scale function)."""
    d = Show(source, view)
    d.Representation = "Point Gaussian"
    d.ShaderPreset = "Plain circle"
    d.ScaleByArray = 1
    d.SetScaleArray = ["POINTS", "radius"]
    d.UseScaleFunction = 1 if through_function else 0
    d.GaussianRadius = scale
    return d


def section_camera(view, x, y, half_height):
    view.InteractionMode = "2D"
    view.CameraPosition = [x, y, 1.0]
    view.CameraFocalPoint = [x, y, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half_height


def nice_step(span):
    """1, 2 or 5 times a power of ten, near `span`."""
    power = 10.0 ** math.floor(math.log10(span))
    for m in (1.0, 2.0, 5.0, 10.0):
        if m * power >= span:
            return m * power
    return 10.0 * power


def decimals(step):
    return builtins.max(0, -int(math.floor(math.log10(step) + 1e-9)))


def label_text(value, step, pad=""):
    # ParaView 5.11's chart measures its labels narrower than it draws them and puts the axis
    # title over their first digits: the padding makes room.
    return pad + "%.*f" % (decimals(step), value)


# Not `percentile`: running a Python filter puts all of numpy into __main__, which is this
# script, and numpy's percentile (q in per cent) would replace a function of that name.
def fraction_point(values, q):
    """The value below which a fraction `q` of `values` lies (nearest rank)."""
    values = builtins.sorted(values)
    if not values:
        return None
    k = builtins.min(len(values) - 1, builtins.max(0, int(builtins.round(q * (len(values) - 1)))))
    return values[k]


def suspension_range(mean, time):
    """The range of the suspension's (running-mean) density at `time`, the bed left out:
    its 1st to 99th percentile, so that neither the bed's edge nor one odd layer sets it."""
    mean.UpdatePipeline(time)
    data = servermanager.Fetch(mean)
    rho = data.GetPointData().GetArray("suspension_density_mean")
    bed = data.GetPointData().GetArray("bed")
    values = [rho.GetValue(k) for k in range(0, data.GetNumberOfPoints(), 2)
              if bed.GetValue(k) == 0]
    if not values:
        values = [rho.GetValue(k) for k in range(0, data.GetNumberOfPoints(), 2)]
    low, high = fraction_point(values, 0.01), fraction_point(values, 0.99)
    if high - low < 1e-3:
        high = low + 1.0
    return low, high


def bed_top(fields, time, height):
    """The height of the bed's surface (the top of its highest layer), 0 without a bed."""
    fields.UpdatePipeline(time)
    data = servermanager.Fetch(fields)
    bed = data.GetPointData().GetArray("bed")
    depth = data.GetPointData().GetArray("depth")
    layers = data.GetNumberOfPoints() // 2
    if bed is None or depth is None or layers == 0:
        return 0.0
    thickness = height / layers
    tops = [height - depth.GetValue(2 * j) + 0.5 * thickness for j in range(layers)
            if bed.GetValue(2 * j) != 0]
    return builtins.max(tops) if tops else 0.0


def zoom_window(particles, time, surface, aspect):
    """Where the zoom looks and how far: (x, y, half height, grains in it, largest diameter,
    median diameter). On the bed's surface when there is a bed (grains packed, the largest of
    them there), else on the largest grains; the window holds about ZOOM_GRAINS grains, and is
    made smaller where that would draw their median grain under ZOOM_DISC_PX pixels across.
    `aspect` is the view's width over its height."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    particles.UpdatePipeline(time)
    data = servermanager.Fetch(particles)
    n = data.GetNumberOfPoints()
    if n == 0:
        return 0.0, surface, 1e-3, 0, 0.0, 0.0
    xy = vtk_to_numpy(data.GetPoints().GetData())[:, :2]
    d = vtk_to_numpy(data.GetPointData().GetArray("diameter"))
    if surface > 0:
        # The bed's surface a third of the way down the window: the bed below, grains above.
        cx, cy = 0.0, surface
    else:
        largest = d >= np.quantile(d, 0.95)
        cx, cy = 0.0, float(np.median(xy[largest, 1]))
    # Distance in the window's own shape: a grain at `r` is inside a window of half height r.
    r = np.maximum(np.abs(xy[:, 0] - cx) / aspect, np.abs(xy[:, 1] - cy))
    order = np.argsort(r)
    k = builtins.min(ZOOM_GRAINS, n) - 1
    half = float(r[order[k]])
    inside = d[order[: k + 1]]
    # Discs of at least ZOOM_DISC_PX pixels for the median grain.
    half = builtins.min(half, float(np.median(inside)) * HEIGHT_PX / (2.0 * ZOOM_DISC_PX))
    half = builtins.max(half, 3.0 * float(d[order[0]]))
    if surface > 0:
        cy = surface - half / 3.0
        r = np.maximum(np.abs(xy[:, 0] - cx) / aspect, np.abs(xy[:, 1] - cy))
    shown = d[r <= half]
    if shown.size == 0:
        shown = d[order[:1]]
    return cx, cy, half, int(shown.size), float(shown.max()), float(np.median(shown))


def main():
    run, time, screenshot, state = arguments(sys.argv[1:])
    # The cameras are set below: the first render must not reset them to the data's bounds.
    paraview.simple._DisableFirstRenderCameraReset()
    particles = open_series(run, "particles")
    fields = open_series(run, "fields")
    hydrometer = open_series(run, "hydrometer")
    if particles is None and fields is None:
        sys.exit("sedem_paraview.py: no particles.pvd or fields.pvd in " + run)

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    times = list(GetTimeKeeper().TimestepValues)
    if time is None:
        time = times[-1] if times else 0.0
    scene.AnimationTime = time

    height, width = 0.457, 0.0635  # m, refined from the data below
    if fields is not None:
        fields.UpdatePipeline(time)
        info = fields.GetDataInformation()
        bounds = info.GetBounds()
        # The strip runs from the top layer's centre to the bottom one's, across the section.
        layer = (bounds[3] - bounds[2]) / builtins.max(1, info.GetNumberOfPoints() / 2 - 1)
        height, width = bounds[3] + 0.5 * layer, bounds[1] - bounds[0]
    elif particles is not None:
        particles.UpdatePipeline(time)
        bounds = particles.GetDataInformation().GetBounds()
        height, width = bounds[3], bounds[1] - bounds[0]

    layout = CreateLayout("sedem")
    layout.SetSize(WIDTH, HEIGHT_PX)
    column_px = int(0.3 * WIDTH)
    column = white_render_view([column_px, HEIGHT_PX])
    AssignViewToLayout(view=column, layout=layout, hint=0)
    zoom = white_render_view([column_px, HEIGHT_PX])
    chart = CreateView("XYChartView")
    chart.ViewSize = [WIDTH - 2 * column_px, HEIGHT_PX]
    chart.ShowLegend = 1
    chart.LegendLocation = "TopRight"
    chart.LegendFontSize = 13
    chart.ChartTitle = "Layers (Eq. 20)"
    chart.ChartTitleFontSize = 16
    chart.LeftAxisTitle = "suspension density (kg/m³)"
    chart.LeftAxisTitleFontSize = 14
    chart.LeftAxisLabelFontSize = 13
    chart.BottomAxisTitle = "depth below the free surface (m)"
    chart.BottomAxisTitleFontSize = 14
    chart.BottomAxisLabelFontSize = 13
    layout.SplitHorizontal(0, 0.3)
    layout.AssignView(2, zoom)
    layout.SplitHorizontal(2, 0.3 / 0.7)
    layout.AssignView(6, chart)
    column_half = 0.52 * height
    surface = 0.0  # the bed's surface, m above the bottom; 0 without a bed
    pixel = 2.0 * column_half / HEIGHT_PX  # m per pixel in the column view

    if fields is not None:
        mean = ProgrammableFilter(registrationName="suspension density, running mean",
                                  Input=fields)
        mean.Script = MEAN_SCRIPT
        low, high = suspension_range(mean, time)
        surface = bed_top(fields, time, height)
        print("sedem_paraview: strip %.6g %.6g bed %.6g" % (low, high, surface))
        f = Show(mean, column)
        f.Ambient, f.Diffuse = 1.0, 0.0  # unlit: the colour is the density's
        ColorBy(f, ("POINTS", "suspension_density_mean"))
        lut = GetColorTransferFunction("suspension_density_mean")
        lut.ApplyPreset("Blues", True)
        lut.InvertTransferFunction()  # clear water white, the densest suspension dark blue
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(low, high)
        bar = GetScalarBar(lut, column)
        black_text(bar, "suspension density (kg/m³)\nover %.0f mm, bed apart" % (
            1e3 * SMOOTH * height))
        bar.RangeLabelFormat = "%-#.1f"
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = "%-.0f"
        bar.WindowLocation = "Upper Left Corner"
        f.SetScalarBarVisibility(column, True)

        # The bed: its layers (flag `bed`) in front of the strip, in one colour.
        bed = Threshold(registrationName="bed", Input=fields)
        bed.Scalars = ["POINTS", "bed"]
        bed.LowerThreshold, bed.UpperThreshold = 0.5, 1.5
        bed.AllScalars = 1
        lifted = Transform(registrationName="bed, in front of the strip", Input=bed)
        lifted.Transform.Translate = [0.0, 0.0, 0.0005]
        b = Show(lifted, column)
        ColorBy(b, None)
        b.Ambient, b.Diffuse = 1.0, 0.0
        b.AmbientColor = b.DiffuseColor = BED_COLOUR
        label = Text(registrationName="bed label")
        label.Text = "brown: the bed"
        t = Show(label, column)
        t.Color = BED_COLOUR
        t.FontSize = 14
        t.WindowLocation = "Lower Left Corner"

        c = Show(mean, chart)
        c.UseIndexForXAxis = 0
        c.XArrayName = "depth"
        c.SeriesVisibility = ["suspension_density", "suspension_density_mean"]
        c.SeriesLabel = ["suspension_density", "each layer",
                         "suspension_density_mean", "mean over %.0f mm" % (1e3 * SMOOTH * height)]
        c.SeriesColor = ["suspension_density", "0.7", "0.7", "0.75",
                         "suspension_density_mean", "0", "0.25", "0.6"]
        c.SeriesLineThickness = ["suspension_density", "1", "suspension_density_mean", "3"]
        margin = 0.08 * (high - low)
        chart.LeftAxisUseCustomRange = 1
        chart.LeftAxisRangeMinimum = low - margin
        chart.LeftAxisRangeMaximum = high + 3 * margin
        chart.BottomAxisUseCustomRange = 1
        chart.BottomAxisRangeMinimum = 0.0
        chart.BottomAxisRangeMaximum = height
        # Labels of our own, in fixed notation: ParaView's own ticks on a range of a few kg/m³
        # come out as long labels that its axis lays out too narrow.
        step = nice_step((high - low) / 5.0)
        first = step * math.ceil((low - margin) / step)
        ticks = [first + k * step for k in range(int((high + 3 * margin - first) / step) + 1)]
        chart.LeftAxisUseCustomLabels = 1
        chart.LeftAxisLabels = [v for t in ticks for v in (repr(t), label_text(t, step, "    "))]
        chart.LeftAxisLabelNotation = "Fixed"
        chart.LeftAxisLabelPrecision = decimals(step)
        chart.BottomAxisUseCustomLabels = 1
        depth_step = nice_step(height / 5.0)
        chart.BottomAxisLabels = [v for k in range(int(height / depth_step) + 1)
                                  for v in (repr(k * depth_step), label_text(k * depth_step, depth_step))]
        chart.BottomAxisLabelNotation = "Fixed"
        chart.BottomAxisLabelPrecision = decimals(depth_step)

    if hydrometer is not None:
        d = Show(hydrometer, column)
        d.Representation = "Surface"
        d.Ambient, d.Diffuse = 0.4, 0.6
        d.AmbientColor = d.DiffuseColor = [0.3, 0.3, 0.35]
        d.Opacity = 0.45
        d.LineWidth = 2.0

    if particles is not None:
        micrometres = Calculator(registrationName="diameter in um", Input=particles)
        micrometres.ResultArrayName = "diameter_um"
        micrometres.Function = "diameter*1e6"
        particles.UpdatePipeline(time)
        info = particles.GetDataInformation()
        n = info.GetNumberOfPoints()
        radii = info.GetPointDataInformation().GetArrayInformation("radius").GetComponentRange(0)
        lut = GetColorTransferFunction("diameter_um")
        lut.ApplyPreset("Viridis (matplotlib)", True)
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(2e6 * radii[0], 2e6 * builtins.max(radii[1], radii[0] * 1.001))

        # The column: a sample of the grains, dots from 1.5 to 5 pixels across by diameter.
        sample = MaskPoints(registrationName="grains shown in the column", Input=micrometres)
        sample.OnRatio = builtins.max(1, -(-n // COLUMN_GRAINS))
        sample.MaximumNumberofPoints = COLUMN_GRAINS
        sample.GenerateVertices = 1
        sample.SingleVertexPerCell = 1
        p = discs(sample, column, pixel, True)
        p.ScaleTransferFunction.Points = [radii[0], 0.75, 0.5, 0.0,
                                          builtins.max(radii[1], radii[0] * 1.001), 2.5, 0.5, 0.0]
        ColorBy(p, ("POINTS", "diameter_um"))
        bar = GetScalarBar(lut, column)
        black_text(bar, "diameter (µm)")
        bar.RangeLabelFormat = "%-#.1f"
        bar.WindowLocation = "Upper Right Corner"
        p.SetScalarBarVisibility(column, True)
        shown = builtins.min(n, COLUMN_GRAINS)
        note = Text(registrationName="column grains")
        note.Text = "%d of %d grains, dots\nsized by diameter" % (shown, n) if shown < n else \
            "%d grains, dots\nsized by diameter" % n
        t = Show(note, column)
        t.Color = [0.0, 0.0, 0.0]
        t.FontSize = 14
        t.WindowLocation = "Lower Right Corner"

        # The zoom: every grain a disc at its true size, where the grains are (the bed's
        # surface, else the largest grains), small enough that the discs are several pixels.
        zx, zy, half, count, largest, median = zoom_window(particles, time, surface,
                                                           float(column_px) / HEIGHT_PX)
        g = discs(micrometres, zoom, 1.0, False)
        ColorBy(g, ("POINTS", "diameter_um"))
        g.SetScalarBarVisibility(zoom, False)
        # Every grain's centre as a dot in front of the discs: grains smaller than a pixel show.
        lifted = Transform(registrationName="grain centres", Input=particles)
        lifted.Transform.Translate = [0.0, 0.0, 1e-6]
        centres = Show(lifted, zoom)
        centres.Representation = "Points"
        centres.PointSize = 2
        ColorBy(centres, None)
        centres.AmbientColor = centres.DiffuseColor = [0.15, 0.15, 0.15]
        section_camera(zoom, zx, zy, half)
        px = HEIGHT_PX / (2.0 * half)  # pixels per metre in the zoom
        label = Text(registrationName="zoom window")
        label.Text = ("discs at each grain's true diameter\n"
                      "window %.2g mm high at %.2g mm%s\n"
                      "(red frame in the column)\n"
                      "%d grains: median %.0f µm = %.0f px,\nlargest %.0f µm = %.0f px" % (
                          2e3 * half, 1e3 * zy, ", the bed's top" if surface > 0 else "",
                          count, 1e6 * median, median * px, 1e6 * largest, largest * px))
        t = Show(label, zoom)
        t.Color = [0.0, 0.0, 0.0]
        t.FontSize = 14
        t.WindowLocation = "Upper Center"
        # Where the zoom is, in the column: a red frame (at least 10 px, to be seen).
        marker = Box(registrationName="zoom window in the column")
        marker.XLength = builtins.max(2.0 * half * column_px / HEIGHT_PX, 10 * pixel)
        marker.YLength = builtins.max(2.0 * half, 10 * pixel)
        marker.ZLength = 0.0
        marker.Center = [zx, zy, 0.001]
        m = Show(marker, column)
        m.Representation = "Outline"
        m.ColorArrayName = ["POINTS", ""]
        m.AmbientColor = m.DiffuseColor = ZOOM_COLOUR
        m.LineWidth = 2.0
        print("sedem_paraview: zoom %.6g %.6g %.6g %d %.6g %.6g" % (
            zx, zy, half, count, median, largest))

    # Last: showing the first data in a view resets its camera.
    section_camera(column, 0.0, 0.5 * height, column_half)
    scene.AnimationTime = time
    if state:
        SaveState(state)
    if screenshot:
        # Charts lay out their axes from the size of their last render: render each view at
        # the screenshot's size first, or the labels are placed for another size and clipped.
        layout.SetSize(WIDTH, HEIGHT_PX)
        for _ in range(2):
            for view in (column, zoom, chart):
                Render(view)
        SaveScreenshot(screenshot, layout, ImageResolution=[WIDTH, HEIGHT_PX],
                       FontScaling="Do not scale fonts")


main()
