"""A surface remeshed by the QuadCover plugin in ParaView, its quads coloured by Valence, as a PNG.

    xvfb-run -a -s -noreset pvbatch paraview_screenshot.py PLUGIN INPUT OUTPUT.png [--quads N]
        [--size W H]

PLUGIN is the plugin library (build/lib/paraview-5.11/plugins/QuadCover/QuadCover.so in a build
tree); INPUT any surface ParaView opens (.obj .ply .stl .vtp .vtk ...). Debian's pvbatch renders
only under an X server: xvfb-run gives it one, kept from resetting (-noreset) when pvbatch's
first connection closes, or the render may find it gone ("bad X server connection").
"""
import argparse

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetDisplayProperties,
                             GetColorTransferFunction, LoadPlugin, OpenDataFile, ResetCamera,
                             SaveScreenshot, Show, Triangulate)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("plugin")
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--quads", type=int, default=2000)
    parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
    args = parser.parse_args()

    LoadPlugin(args.plugin, remote=False, ns=globals())
    surface = Triangulate(Input=OpenDataFile(args.input))
    quads = QuadCoverRemesh(Input=surface)  # noqa: F821 (made by LoadPlugin)
    quads.TargetQuadCount = args.quads

    view = GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    # ParaView 5.11 takes a background colour of the view's own only with this switch
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    Show(quads, view)
    display = GetDisplayProperties(quads, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.25, 0.25, 0.3]
    # valence 3 blue, 4 (regular) light grey, 5 and more red
    ColorBy(display, ("POINTS", "Valence"))
    lut = GetColorTransferFunction("Valence")
    lut.RGBPoints = [3.0, 0.23, 0.30, 0.75, 4.0, 0.86, 0.86, 0.86, 5.0, 0.71, 0.02, 0.15]
    lut.AutomaticRescaleRangeMode = "Never"
    view.Update()
    ResetCamera(view)
    camera = view.GetActiveCamera()  # a three-quarter view rather than straight down an axis
    camera.Azimuth(35)
    camera.Elevation(25)
    ResetCamera(view)
    SaveScreenshot(args.output, view, ImageResolution=args.size)


if __name__ == "__main__":
    main()
