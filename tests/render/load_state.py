# Loads a ParaView state file as ParaView's File > Load State does and writes its layout as a
# PNG at the size the macro draws it, to compare with the macro's own screenshot.
#   pvpython load_state.py STATE.pvsm OUT.png
import sys

from paraview.simple import GetLayouts, GetViews, LoadState, Render, SaveScreenshot

state, out = sys.argv[1], sys.argv[2]
LoadState(state)
layouts = list(GetLayouts().values())
if len(layouts) != 1:
    sys.exit("load_state.py: %d layouts in %s, one expected" % (len(layouts), state))
layout = layouts[0]
layout.SetSize(1600, 900)
views = GetViews()
for view in views:
    Render(view)
SaveScreenshot(out, layout, ImageResolution=[1600, 900], FontScaling="Do not scale fonts")
print("LOADED %d views" % len(views))
