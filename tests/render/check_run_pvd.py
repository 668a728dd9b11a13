# Opens every .pvd of a sedem run folder through ParaView's own reader and prints, as one JSON
# line, what a user would get: for each series its time values, the data set's class and,
# at its last time, every point and field array's type, components and range, and the
# representation and colouring ParaView picks with no further step.
import glob
import json
import os
import sys

from paraview.simple import CreateView, OpenDataFile, Show, servermanager

view = CreateView("RenderView")
report = {}
for pvd in sorted(glob.glob(os.path.join(sys.argv[1], "*.pvd"))):
    name = os.path.splitext(os.path.basename(pvd))[0]
    reader = OpenDataFile(pvd)
    reader.UpdatePipelineInformation()
    times = [float(t) for t in reader.TimestepValues]
    reader.UpdatePipeline(times[-1])
    data = servermanager.Fetch(reader)

    def arrays(attributes):
        out = {}
        for i in range(attributes.GetNumberOfArrays()):
            a = attributes.GetAbstractArray(i)
            entry = {"type": a.GetDataTypeAsString(), "components": a.GetNumberOfComponents()}
            if hasattr(a, "GetRange"):
                entry["range"] = list(a.GetRange(-1 if a.GetNumberOfComponents() > 1 else 0))
            out[a.GetName()] = entry
        return out

    display = Show(reader, view)
    colour = [str(c) if c else "" for c in display.ColorArrayName]
    report[name] = {
        "times": times,
        "class": data.GetClassName(),
        "points": data.GetNumberOfPoints(),
        "cells": data.GetNumberOfCells(),
        "point_data": arrays(data.GetPointData()),
        "cell_data": arrays(data.GetCellData()),
        "field_data": arrays(data.GetFieldData()),
        "representation": str(display.Representation).strip("'"),
        "colour": colour,
    }
print("REPORT " + json.dumps(report))
