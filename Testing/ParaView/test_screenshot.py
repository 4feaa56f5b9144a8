"""pvbatch renders the plugin's quads on a virtual X server (Examples/Python/paraview_screenshot.py):
the PNG has the size asked for, and shows a mesh (many colours, not a blank view).

The test starts Xvfb itself, waits until it accepts clients (-displayfd), and keeps it from
resetting when its last client leaves (-noreset): pvbatch connects once at start-up and again to
render, and a render that fell into the reset failed with "bad X server connection" (1 run in 2
to 1 in 12 here, never in 16 with -noreset).

    test_screenshot.py PVBATCH PLUGIN SCRIPT INPUT OUTPUT.png
"""
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

pvbatch, plugin, script, surface, output = sys.argv[1:6]
ready, told = os.pipe()
# the X server without the sanitizer runtime a sanitizer build preloads for pvbatch
server_env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(told), "-screen", "0", "1024x768x24",
                         "-noreset", "-nolisten", "tcp"], pass_fds=(told,), env=server_env)
os.close(told)
try:
    display = os.read(ready, 32).decode().strip()  # written once the server accepts clients
    if not display:
        sys.exit("Xvfb did not start")
    env = dict(os.environ, DISPLAY=":" + display)
    subprocess.run([pvbatch, "--no-mpi", script, plugin, surface, output, "--quads", "800", "--size", "640",
                    "480"], check=True, timeout=600, env=env)
finally:
    xvfb.terminate()
    xvfb.wait()
reader = vtkPNGReader()
reader.SetFileName(output)
reader.Update()
image = reader.GetOutput()
dims = image.GetDimensions()
if dims[:2] != (640, 480):
    sys.exit("screenshot of %dx%d pixels, not 640x480" % dims[:2])
pixels = image.GetPointData().GetScalars()
colours = set()
for i in range(0, pixels.GetNumberOfTuples(), 7):
    colours.add(tuple(int(pixels.GetComponent(i, c)) for c in range(3)))
background = sum(1 for i in range(0, pixels.GetNumberOfTuples(), 7)
                 if tuple(int(pixels.GetComponent(i, c)) for c in range(3)) == (255, 255, 255))
share = background / ((pixels.GetNumberOfTuples() + 6) // 7)
if len(colours) < 20 or share > 0.95:
    sys.exit("screenshot shows no mesh: %d colours, %.0f%% background" % (len(colours), 100 * share))
print("screenshot: %dx%d, %d colours, %.0f%% background" % (dims[0], dims[1], len(colours),
                                                          100 * share))
