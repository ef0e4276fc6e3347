# A real client of the result files: ParaView opens a result's XDMF view (engine/io/xdmf.*, written
# beside every complete result) and renders the spheres of its last frame, each a sphere of its own
# radius, translucent and coloured by the radius, the cell's outline and, if the result has frames
# with contacts (output.frames.contacts), the contact forces as tubes whose radius grows with the
# normal force, to a PNG. Run through render.sh (`dem render RESULT.h5 --out OUT.png`, `make render`),
# which gives pvbatch a virtual X display:
#   reports/render/render.sh RESULT.xdmf OUT.png [TITLE]
# (Python only as a client script: the project's own code is C++.)
import sys

from paraview.simple import (Calculator, CellDatatoPointData, ColorBy, ExtractSurface, GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, Glyph, Render,
                             SaveScreenshot, Show, Text, Tube, XDMFReader)

if len(sys.argv) < 3:
    sys.exit("usage: pvbatch render_spheres.py RESULT.xdmf OUT.png [TITLE]")
xdmf, png = sys.argv[1], sys.argv[2]
title = sys.argv[3] if len(sys.argv) > 3 else xdmf

def grid(name):
    """A reader of one kind of the XDMF's grids (particles, cell, contacts), or None if it has none.
    Results written before the cell and contact views have only particle grids ("frame N")."""
    r = XDMFReader(FileNames=[xdmf])
    r.UpdatePipelineInformation()
    available = list(r.GridStatus.Available)
    mine = [g for g in available if g.split("[")[0] == name]
    if not mine and name == "particles" and not any(g.split("[")[0] in ("cell", "contacts") for g in available):
        mine = available
    if not mine:
        return None
    r.GridStatus = mine
    return r


reader = grid("particles")
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
reader.UpdatePipeline(times[-1])
points = reader.GetDataInformation().GetNumberOfPoints()
if points == 0:
    sys.exit(f"{xdmf}: no particles in the last frame")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1100, 1000]
view.ViewTime = times[-1]
view.Background = [1, 1, 1]
try:  # ParaView >= 5.10 keeps the background in a palette unless told otherwise
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.OrientationAxesVisibility = 1

# The default sphere glyph has radius 0.5: scaled by 2 x radius it is the particle itself.
spheres = Glyph(Input=reader, GlyphType="Sphere")
spheres.ScaleArray = ["POINTS", "radius"]
spheres.ScaleFactor = 2.0
spheres.GlyphMode = "All Points"
spheres.GlyphType.ThetaResolution = 16
spheres.GlyphType.PhiResolution = 12
display = Show(spheres, view)
display.Opacity = 0.5  # translucent: the cell's far edges and the grains behind show through


def colour(shown, array, preset, title):
    """Colours `shown` by the point array `array` with a black-on-white scalar bar; returns the bar."""
    ColorBy(shown, ("POINTS", array))
    lut = GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    return bar


colour(display, "radius", "Viridis (matplotlib)", "radius (m)").RangeLabelFormat = "%-#.2e"

# The cell, and the contact network as tubes (radius and colour by the normal force), if present.
cell = grid("cell")
if cell is not None:
    outline = Show(cell, view)
    outline.SetRepresentationType("Wireframe")  # the XDMF's cell is its 12 edges
    outline.AmbientColor = outline.DiffuseColor = [0, 0, 0]
    outline.LineWidth = 2
contacts = grid("contacts")
forces = ""
if contacts is not None:
    contacts.UpdatePipeline(times[-1])
    lines = contacts.GetDataInformation().GetNumberOfCells()
    if lines > 0:
        display.Opacity = 0.15  # the spheres fade so that the force chains show
        fmax = contacts.CellData["normal_force"].GetRange()[1]
        # The XDMF's lines arrive as an unstructured grid; the tube filter takes polygonal data only,
        # and "By Absolute Scalar" makes the scalar the radius itself [m]: the largest force 1 mm.
        radius = Calculator(Input=ExtractSurface(Input=CellDatatoPointData(Input=contacts)))
        radius.AttributeType = "Point Data"
        radius.ResultArrayName = "tube_radius"
        radius.Function = f"normal_force * {1.0e-3 / fmax if fmax > 0 else 0.0}"
        tubes = Tube(Input=radius)
        tubes.Scalars = ["POINTS", "tube_radius"]
        tubes.VaryRadius = "By Absolute Scalar"
        tubes.Radius = 1.0e-5  # the thinnest tube (zero forces)
        tubes.NumberofSides = 8
        tube_display = Show(tubes, view)
        colour(tube_display, "normal_force", "Inferno (matplotlib)", "normal force (N)").WindowLocation = "Upper Right Corner"
        forces = f", {lines} contacts as tubes (radius by the normal force, largest {fmax:.3g} N)"

label = Text(Text=f"{title}\n{points} spheres at t = {times[-1]:.4g} s{forces} (ParaView, XDMF)")
label_display = Show(label, view)
label_display.Color = [0, 0, 0]
label_display.FontSize = 14
label_display.WindowLocation = "Upper Left Corner"

# Axis 1 (x of the result) vertical, as the paper's Fig. 2.
view.CameraPosition = [0.9, 1.6, -1.0]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [1, 0, 0]
view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[1100, 1000])
print(f"rendered {points} spheres of {xdmf} at t = {times[-1]:.6g} s{forces} -> {png}")
