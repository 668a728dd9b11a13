# Opens a sedem run in ParaView the way the paper shows it.
#
#   pvpython docs/sedem_paraview.py RUN_DIR [--time T] [--screenshot FILE.png] [--state FILE.pvsm]
#   paraview --script=docs/sedem_paraview.py      (RUN_DIR from SEDEM_RUN, or the current folder)
#
# In the ParaView GUI it can also be added once with Macros > Import new macro... and run
# from the toolbar after setting SEDEM_RUN (or starting ParaView in the run's folder).
#
# Three views, all on the same time (play the VCR controls and they move together):
#   - the column: the section face on (2D camera), the layers' suspension density behind the
#     grains, the grains as dots coloured by diameter, the hydrometer's bulb translucent;
#   - a zoom on a few grains at 0.3 H below the free surface: the grains as discs at their true
#     size, coloured by diameter (at the column's scale a 70 um grain is far below a pixel);
#   - the layer fields (suspension density) against depth.
# --screenshot writes the three views as one PNG; --state saves a ParaView state file.
import os
import sys

from paraview.simple import (
    AssignViewToLayout, ColorBy, CreateLayout, CreateView, GetAnimationScene,
    GetColorTransferFunction, GetScalarBar, GetTimeKeeper, PVDReader, SaveScreenshot, SaveState, Show, Text,
    servermanager)

HEIGHT = 0.457  # m, refined from the data below


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
    return PVDReader(registrationName=name, FileName=path)


def colour_by_diameter(display, view):
    ColorBy(display, ("POINTS", "diameter"))
    lut = GetColorTransferFunction("diameter")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "diameter (m)"
    bar.RangeLabelFormat = "%-#6.1e"
    black_text(bar)
    display.SetScalarBarVisibility(view, True)


def black_text(bar):
    bar.ComponentTitle = ""
    bar.TitleColor = [0.0, 0.0, 0.0]
    bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 14
    bar.LabelFontSize = 12


def white_render_view():
    view = CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    return view


def bulb(hydrometer, view):
    d = Show(hydrometer, view)
    d.Representation = "Surface"
    d.AmbientColor = d.DiffuseColor = [0.55, 0.55, 0.6]
    d.Opacity = 0.3
    return d


def section_camera(view, centre_y, half_height):
    view.InteractionMode = "2D"
    view.CameraPosition = [0.0, centre_y, 1.0]
    view.CameraFocalPoint = [0.0, centre_y, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half_height


def zoom_target(particles, time):
    """The grain nearest the axis at 0.3 H below the free surface, and its diameter."""
    particles.UpdatePipeline(time)
    data = servermanager.Fetch(particles)
    n = data.GetNumberOfPoints()
    diameters = data.GetPointData().GetArray("diameter")
    target_y = 0.7 * HEIGHT
    best, best_d2, diameter = (0.0, target_y), None, 1e-5
    for i in range(n):
        x, y, _ = data.GetPoint(i)
        d2 = x * x + (y - target_y) ** 2
        if best_d2 is None or d2 < best_d2:
            best, best_d2, diameter = (x, y), d2, diameters.GetValue(i)
    return best, diameter


def main():
    global HEIGHT
    run, time, screenshot, state = arguments(sys.argv[1:])
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

    if fields is not None:
        fields.UpdatePipeline(time)
        bounds = fields.GetDataInformation().GetBounds()
        # The strip runs from the top layer's centre to the bottom one's.
        layer = (bounds[3] - bounds[2]) / max(1, fields.GetDataInformation().GetNumberOfPoints() / 2 - 1)
        HEIGHT = bounds[3] + 0.5 * layer

    layout = CreateLayout("sedem")
    column = white_render_view()
    AssignViewToLayout(view=column, layout=layout, hint=0)
    zoom = white_render_view()
    chart = CreateView("XYChartView")
    chart.ChartTitleFontSize = 16
    chart.LeftAxisTitleFontSize = 12
    chart.BottomAxisTitleFontSize = 12
    chart.ShowLegend = 0
    chart.LeftAxisTitle = "suspension density (kg/m³)"
    chart.BottomAxisTitle = "depth below the free surface (m)"
    chart.ChartTitle = "Layers (Eq. 20)"
    chart.LegendLocation = "TopLeft"
    layout.SplitHorizontal(0, 0.34)
    layout.AssignView(2, zoom)
    layout.SplitHorizontal(2, 0.5)
    layout.AssignView(6, chart)

    if fields is not None:
        f = Show(fields, column)
        f.Ambient, f.Diffuse = 1.0, 0.0  # unlit: the colour is the density's
        ColorBy(f, ("POINTS", "suspension_density"))
        lut = GetColorTransferFunction("suspension_density")
        lut.ApplyPreset("Blues", True)
        lut.InvertTransferFunction()  # clear water white, the bed dark
        f.RescaleTransferFunctionToDataRange(False, True)
        bar = GetScalarBar(lut, column)
        bar.Title = "suspension density (kg/m³)"
        black_text(bar)
        bar.WindowLocation = "Upper Left Corner"
        f.SetScalarBarVisibility(column, True)
        c = Show(fields, chart)
        c.UseIndexForXAxis = 0
        c.XArrayName = "depth"
        c.SeriesVisibility = ["suspension_density"]
        c.SeriesColor = ["suspension_density", "0", "0.3", "0.7"]
        c.SeriesLineThickness = ["suspension_density", "2"]

    if particles is not None:
        p = Show(particles, column)
        p.Representation = "Points"
        p.PointSize = 3
        p.RenderPointsAsSpheres = 1
        colour_by_diameter(p, column)
        g = Show(particles, zoom)
        g.Representation = "Point Gaussian"
        g.ShaderPreset = "Plain circle"
        g.ScaleByArray = 1
        g.SetScaleArray = ["POINTS", "radius"]
        g.UseScaleFunction = 0
        g.GaussianRadius = 1.0
        ColorBy(g, ("POINTS", "diameter"))
        g.SetScalarBarVisibility(zoom, False)
        (zx, zy), diameter = zoom_target(particles, time)
        # Fifteen of its diameters across the window: the grain is a disc, not a dot.
        section_camera(zoom, zy, 7.5 * diameter)
        label = Text(registrationName="zoom window")
        label.Text = "true size: window %.2g mm high\ngrain of %.3g µm at y = %.3g m" % (
            15e3 * diameter, 1e6 * diameter, zy)
        t = Show(label, zoom)
        t.Color = [0.0, 0.0, 0.0]
        t.FontSize = 14
        t.WindowLocation = "Upper Center"
        zoom.CameraPosition = [zx, zy, 1.0]
        zoom.CameraFocalPoint = [zx, zy, 0.0]

    if hydrometer is not None:
        bulb(hydrometer, column)

    section_camera(column, 0.5 * HEIGHT, 0.52 * HEIGHT)
    scene.AnimationTime = time

    if state:
        SaveState(state)
    if screenshot:
        SaveScreenshot(screenshot, layout, ImageResolution=[1500, 600])


main()
