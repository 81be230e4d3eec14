"""Checks argine's Exodus results in real ParaView and renders a picture.

Usage (under a virtual X server):
  xvfb-run -a pvpython check_exodus.py GRID POINTS EXPECTED_POINTS OUT.png [EXPECTED_TIMES]

GRID and POINTS are the files written by argine's ResultsWriter (<stem>_grid.e and
<stem>_points.e, ParaView reads its restart files -s0002... with it), EXPECTED_POINTS the
number of material points at the first time, OUT.png the
picture to write (the points coloured by pressure_liquid over the grid, at the last time),
EXPECTED_TIMES an optional comma-separated list of the written times. Exits non-zero with a
message saying what is wrong on any failure.
"""
import math
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, ExodusIIReader, GetColorTransferFunction,
                             GetScalarBar, ResetCamera, SaveScreenshot, Show)

# Nodal arrays of the points file as ParaView groups them: name -> number of components.
# Vectors _x/_y become 3-component arrays named with the trailing "_"; the 6 suffixes
# xx yy zz xy xz yz become a symmetric tensor.
EXPECTED_POINT_ARRAYS = {
    "displ_": 3,
    "displacement_": 3,
    "velocity_solid_": 3,
    "velocity_liquid_": 3,
    "pressure_liquid": 1,
    "suction": 1,
    "saturation": 1,
    "conductivity": 1,
    "porosity": 1,
    "stress_eff_": 6,
    "deviatoric_strain": 1,
    "plastic_strain": 1,
    "plastic_state": 1,
    "material": 1,
    "volume": 1,
    "point_id": 1,
}


def fail(message):
    print("paraview check FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def open_exodus(path):
    if not os.path.isfile(path):
        fail("%s does not exist" % path)
    reader = ExodusIIReader(FileName=[path])
    reader.PointVariables = reader.PointVariables.Available
    reader.ElementBlocks = reader.ElementBlocks.Available
    reader.ApplyDisplacements = 1
    reader.UpdatePipeline()
    return reader


def leaf_datasets(data):
    """The unstructured grids inside the multiblock dataset the Exodus reader makes."""
    if data.IsA("vtkMultiBlockDataSet"):
        for i in range(data.GetNumberOfBlocks()):
            block = data.GetBlock(i)
            if block is not None:
                yield from leaf_datasets(block)
    elif data.GetNumberOfPoints() > 0:
        yield data


def points_at(reader, time):
    """point_id -> ((x, y), (displ_x, displ_y)) of every point at `time`."""
    reader.UpdatePipeline(time)
    result = {}
    for grid in leaf_datasets(servermanager.Fetch(reader)):
        ids = grid.GetPointData().GetArray("point_id")
        displ = grid.GetPointData().GetArray("displ_")
        if ids is None or displ is None:
            fail("a block of the points file has no point_id or displ_ array")
        for n in range(grid.GetNumberOfPoints()):
            x = grid.GetPoint(n)
            d = displ.GetTuple3(n)
            result[int(ids.GetValue(n))] = ((x[0], x[1]), (d[0], d[1]))
    return result


def check_displacements_applied(path, reader, time):
    """ParaView must draw each point at its file's reference position + displ_."""
    moved = points_at(reader, time)
    reader.ApplyDisplacements = 0
    reference = points_at(reader, time)
    reader.ApplyDisplacements = 1
    largest = 0.0
    for pid, ((x, y), (dx, dy)) in moved.items():
        (x0, y0), _ = reference[pid]
        largest = max(largest, math.hypot(dx, dy))
        # Coordinates come back as float32: compare with a float tolerance.
        tolerance = 1e-5 * (1.0 + abs(x0) + abs(y0))
        if abs(x - x0 - dx) > tolerance or abs(y - y0 - dy) > tolerance:
            fail("%s at t = %g: point %d drawn %g, %g from its reference but displ_ is %g, %g:"
                 " ParaView does not apply displ_" % (path, time, pid, x - x0, y - y0, dx, dy))
    return largest


def check_times(name, reader, expected):
    times = list(reader.TimestepValues or [])
    if expected is not None:
        if len(times) != len(expected) or any(
                abs(a - b) > 1e-9 * (1 + abs(b)) for a, b in zip(times, expected)):
            fail("%s: time steps %s, expected %s" % (name, times, expected))
    elif not times:
        fail("%s: no time steps" % name)
    if any(b <= a for a, b in zip(times, times[1:])):
        fail("%s: time values not increasing: %s" % (name, times))
    return times


def check_points_file(path, expected_points, expected_times):
    reader = open_exodus(path)
    info = reader.GetDataInformation()  # at the first time
    if info.GetNumberOfPoints() != expected_points:
        fail("%s: %d points at the first time, expected %d" %
             (path, info.GetNumberOfPoints(), expected_points))
    if info.GetNumberOfCells() != expected_points:
        fail("%s: %d cells, expected one per point (%d)" %
             (path, info.GetNumberOfCells(), expected_points))
    blocks = list(reader.ElementBlocks.Available)
    if not blocks:
        fail("%s: no element blocks (one per material expected)" % path)
    arrays = reader.PointData
    for name, components in EXPECTED_POINT_ARRAYS.items():
        if name not in arrays.keys():
            fail("%s: no point array %s (arrays: %s)" % (path, name, sorted(arrays.keys())))
        if arrays[name].GetNumberOfComponents() != components:
            fail("%s: %s has %d components, expected %d" %
                 (path, name, arrays[name].GetNumberOfComponents(), components))
    times = check_times(path, reader, expected_times)

    counts = []
    for time in times:
        reader.UpdatePipeline(time)
        counts.append(reader.GetDataInformation().GetNumberOfPoints())
    largest = max(check_displacements_applied(path, reader, time) for time in times)
    if largest == 0.0:
        print("warning: displ_ is zero at every time, so applying it was not tested")
    # A restart series (<file>-s0002, ...) shows up as a change of the point count.
    print("points file: %d points at t = %g, blocks %s, times %s, points per time %s, "
          "largest displ_ %.4g m" %
          (expected_points, times[0], blocks, times, counts, largest))
    return reader, times


def check_grid_file(path, expected_times):
    reader = open_exodus(path)
    info = reader.GetDataInformation()
    if info.GetNumberOfPoints() == 0 or info.GetNumberOfCells() == 0:
        fail("%s: empty mesh (%d nodes, %d cells)" %
             (path, info.GetNumberOfPoints(), info.GetNumberOfCells()))
    times = check_times(path, reader, expected_times)
    print("grid file: %d nodes, %d cells, blocks %s, nodal fields %s" %
          (info.GetNumberOfPoints(), info.GetNumberOfCells(),
           list(reader.ElementBlocks.Available), list(reader.PointVariables.Available)))
    return reader, times


def render(grid, points, time, png):
    view = CreateView("RenderView")
    view.ViewSize = [1000, 600]
    view.OrientationAxesVisibility = 0
    view.InteractionMode = "2D"
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView >= 5.10 uses a palette unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.ViewTime = time
    mesh = Show(grid, view)
    mesh.SetRepresentationType("Wireframe")
    mesh.ColorArrayName = ["POINTS", ""]  # solid colour
    mesh.AmbientColor = mesh.DiffuseColor = [0.5, 0.5, 0.5]
    dots = Show(points, view)
    dots.SetRepresentationType("Points")
    dots.PointSize = 14
    dots.RenderPointsAsSpheres = 1
    ColorBy(dots, ("POINTS", "pressure_liquid"))
    dots.RescaleTransferFunctionToDataRange(True, False)
    dots.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(GetColorTransferFunction("pressure_liquid"), view)
    bar.Title = "pressure_liquid (Pa)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    ResetCamera(view)
    SaveScreenshot(png, view, ImageResolution=[1000, 600])
    if not os.path.isfile(png) or os.path.getsize(png) == 0:
        fail("no picture written to %s" % png)


def check_picture(png):
    """The picture must show more than the background: count its distinct colours."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    image = vtkPNGReader()
    image.SetFileName(png)
    image.Update()
    scalars = image.GetOutput().GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    colours = set()
    for i in range(0, scalars.GetNumberOfTuples(), 7):
        colours.add(tuple(int(scalars.GetComponent(i, c)) for c in range(min(components, 3))))
    if len(colours) < 10:
        fail("%s shows only %d colours: points not rendered" % (png, len(colours)))
    print("picture: %s (%d colours sampled)" % (png, len(colours)))


def main(argv):
    if len(argv) not in (5, 6):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    grid_path, points_path, expected_points, png = argv[1:5]
    try:
        expected_points = int(expected_points)
        expected_times = [float(t) for t in argv[5].split(",")] if len(argv) == 6 else None
    except ValueError as error:
        fail("bad argument: %s" % error)

    points, point_times = check_points_file(points_path, expected_points, expected_times)
    grid, grid_times = check_grid_file(grid_path, expected_times)
    if grid_times != point_times:
        fail("grid times %s differ from points times %s" % (grid_times, point_times))
    render(grid, points, point_times[-1], png)
    check_picture(png)
    print("paraview check passed")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except SystemExit:
        raise
    except Exception as error:  # a ParaView call failed: say so plainly, then the details
        import traceback
        traceback.print_exc()
        fail("%s: %s" % (type(error).__name__, error))
