"""The screenshots of docs/paraview.md, rendered headless:

    xvfb-run -a pvbatch plugins/paraview/examples/screenshots.py docs/images

with the plugin found through PV_PLUGIN_PATH, SUBDIV_PARAVIEW_PLUGIN or the subdivkit module
(PYTHONPATH=build/python). Writes paraview-creased-cube.png (one cube refined three ways:
smooth, creases from a cell array on line cells, creases from the feature angle; coloured
by vertex_class) and paraview-textured-sphere.png (a coarse sphere with texture coordinates,
and Loop's refinement of it carrying them), paraview-spectrum.png (SubdivKit Analyze's
spectrum in a line chart), paraview-levels.png (a cube's levels 0 to 3 side by side,
All Levels with Level Spacing, coloured by origin) and paraview-limit.png (SubdivKit
Limit: a cube's sampled limit surface and its adaptive mesh)."""

import os
import sys

from paraview import simple as pv
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cube_with_lines import FACES, cube_with_lines  # noqa: E402 (beside this script)

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
if not hasattr(pv, "SubdivKitRefine"):  # not loaded at start through PV_PLUGIN_PATH
    if os.environ.get("SUBDIV_PARAVIEW_PLUGIN"):
        pv.LoadPlugin(os.environ["SUBDIV_PARAVIEW_PLUGIN"], remote=False, ns=vars(pv))
    else:
        import subdivkit
        subdivkit.load_paraview_plugin(vars(pv))


def cube_with_crease_lines():
    """The cube's top rim infinitely sharp (10), its bottom rim semi-sharp (2: sharp for two
    levels, then smooth), in the cell array "sharpness_in" (0 on the faces)."""
    rims = [(4, 5, 6, 7, 4), (0, 1, 2, 3, 0)]
    return cube_with_lines(rims, {"sharpness_in": [10.0, 2.0] + [0.0] * len(FACES)}, offset=(-0.5, -0.5, -0.5))


def checker_png(path, squares=8, size=256):
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    image.AllocateScalars(3, 3)  # unsigned char RGB
    cell = size // squares
    for y in range(size):
        for x in range(size):
            dark = ((x // cell) + (y // cell)) % 2
            for c, (a, b) in enumerate(((230, 40), (200, 90), (120, 160))):
                image.SetScalarComponentFromDouble(x, y, 0, c, b if dark else a)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def render_view(size):
    view = pv.CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def colour_by(display, array, top):
    pv.ColorBy(display, ("POINTS", array))
    display.LookupTable = pv.GetColorTransferFunction(array)
    display.LookupTable.ApplyPreset("Rainbow Uniform", True)
    display.LookupTable.RescaleTransferFunction(0, top)


def show(source, view, x, colour=None, representation="Surface With Edges"):
    """source moved by x along x, shown with edges (and coloured by point array `colour`, 0..3)."""
    moved = pv.Transform(Input=source)
    moved.Transform.Translate = [x, 0, 0]
    display = pv.Show(moved, view)
    display.SetRepresentationType(representation)
    if colour:
        colour_by(display, colour, 3)
    return display


def look_from_front(view, centre_x, eye, zoom):
    """A parallel projection of a row of objects along x, from eye = (dx, dy, dz) off (centre_x, 0, 0)."""
    view.CameraParallelProjection = 1
    view.CameraPosition = [centre_x + eye[0], eye[1], eye[2]]
    view.CameraFocalPoint = [centre_x, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    view.CameraParallelScale *= zoom


def creased_cube(path):
    view = render_view([1200, 500])
    cube = pv.Clean(Input=pv.Box())
    lines = cube_with_crease_lines()
    smooth = pv.SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3)
    by_array = pv.SubdivKitRefine(Input=lines, Scheme="catmull-clark", Levels=3, CreaseArray="sharpness_in")
    by_angle = pv.SubdivKitRefine(Input=cube, Scheme="catmull-clark", Levels=3, UseFeatureAngle=1, FeatureAngle=40)
    for i, refined in enumerate((smooth, by_array, by_angle)):
        display = show(refined, view, 1.6 * i, "vertex_class")
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(display.LookupTable, view)
    bar.Title = "vertex_class: 0 smooth, 1 dart, 2 crease, 3 corner"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Lower Center"
    bar.ScalarBarLength = 0.4
    bar.AutomaticLabelFormat = 0
    bar.LabelFormat = bar.RangeLabelFormat = "%.0f"
    bar.UseCustomLabels = 1
    bar.CustomLabels = [0, 1, 2, 3]
    look_from_front(view, 1.6, (2.0, -5.0, 3.0), 0.75)
    view.CameraFocalPoint = [1.6, 0, -0.25]  # room below for the colour bar
    pv.SaveScreenshot(path, view, ImageResolution=[1200, 500])


def textured_sphere(path, texture_png):
    view = render_view([900, 450])
    coarse = pv.TextureMaptoSphere(Input=pv.Sphere(ThetaResolution=8, PhiResolution=6), PreventSeam=1)
    fine = pv.SubdivKitRefine(Input=coarse, Scheme="loop", Levels=3)
    texture = pv.CreateTexture(texture_png)
    for i, source in enumerate((coarse, fine)):
        display = show(source, view, 1.3 * i, representation="Surface" if i else "Surface With Edges")
        display.Texture = texture
    look_from_front(view, 0.65, (0.0, -3.2, 0.8), 0.7)
    pv.SaveScreenshot(path, view, ImageResolution=[900, 450])


def levels_side_by_side(path):
    view = render_view([1200, 360])
    levels = pv.SubdivKitRefine(Input=pv.Clean(Input=pv.Box()), Scheme="catmull-clark", Levels=3, AllLevels=1,
                                LevelSpacing=0.8)
    display = pv.Show(levels, view)
    display.SetRepresentationType("Surface With Edges")
    colour_by(display, "origin", 2)
    look_from_front(view, 2.1, (1.0, -5.0, 1.5), 0.8)
    pv.SaveScreenshot(path, view, ImageResolution=[1200, 360])


def limit_cube(path):
    """The control cube; SubdivKit Limit's sampled limit surface, shaded with its exact
    normals; and the adaptive mesh on the limit, refined only around the cube's eight
    valence-3 vertices, its faces coloured by level."""
    view = render_view([1200, 420])
    cube = pv.Clean(Input=pv.Box())
    sampled = pv.SubdivKitLimit(Input=cube, Scheme="catmull-clark", Samples=16)
    adaptive = pv.SubdivKitLimit(Input=cube, Scheme="catmull-clark", Mode=1, AdaptiveLevels=4)
    show(cube, view, 0.0, representation="Wireframe")
    show(sampled, view, 1.5, representation="Surface")
    display = show(adaptive, view, 3.0)
    pv.ColorBy(display, ("CELLS", "face_level"))
    display.LookupTable = pv.GetColorTransferFunction("face_level")
    display.LookupTable.ApplyPreset("Rainbow Uniform", True)
    display.LookupTable.RescaleTransferFunction(0, 4)
    look_from_front(view, 1.5, (2.0, -5.0, 3.0), 0.6)
    pv.SaveScreenshot(path, view, ImageResolution=[1200, 420])


def spectrum_chart(path):
    analyze = pv.SubdivKitAnalyze(Scheme="loop", Valences=[3, 12], Eigenvalues=6)
    chart = pv.CreateView("XYChartView")
    chart.ViewSize = [800, 450]
    display = pv.Show(pv.OutputPort(analyze, 1), chart)
    display.UseIndexForXAxis = 0
    display.XArrayName = "valence"
    display.SeriesVisibility = ["lambda_1", "lambda_2", "lambda_3", "lambda_4", "lambda_1^2"]
    chart.LeftAxisTitle = "eigenvalue modulus"
    chart.BottomAxisTitle = "valence"
    chart.ChartTitle = "Loop: leading eigenvalues of the subdivision matrix (SubdivKit Analyze)"
    pv.SaveScreenshot(path, chart, ImageResolution=[800, 450])


os.makedirs(out_dir, exist_ok=True)
creased_cube(os.path.join(out_dir, "paraview-creased-cube.png"))
texture = os.path.join(os.environ.get("TMPDIR", "/tmp"), "subdivkit-checker.png")
checker_png(texture)
textured_sphere(os.path.join(out_dir, "paraview-textured-sphere.png"), texture)
spectrum_chart(os.path.join(out_dir, "paraview-spectrum.png"))
levels_side_by_side(os.path.join(out_dir, "paraview-levels.png"))
limit_cube(os.path.join(out_dir, "paraview-limit.png"))
print("wrote", ", ".join(f"{out_dir}/paraview-{n}.png"
                         for n in ("creased-cube", "textured-sphere", "spectrum", "levels", "limit")))
