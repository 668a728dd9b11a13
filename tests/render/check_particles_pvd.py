# Opens a particles.pvd through ParaView's own reader and prints what a user would see:
# the time steps, the point arrays and the point count of the last step.
import sys

from paraview.simple import OpenDataFile

reader = OpenDataFile(sys.argv[1])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
print("times", " ".join(repr(float(t)) for t in times))
reader.UpdatePipeline(times[-1])
print("arrays", " ".join(sorted(reader.PointData.keys())))
print("points", reader.GetDataInformation().GetNumberOfPoints())
