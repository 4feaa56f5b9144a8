"""The ParaView plugin, from pvpython: loads, runs the chain and the one-click filter, and every
property of its XML reaches its VTK filter.

    pvpython test_plugin.py PLUGIN.so

The quadcover Python package must be on PYTHONPATH (the test reads the filters' own defaults and
properties through it). Exits non-zero with a line per failure.
"""
import sys

from paraview import servermanager
from paraview.simple import GroupDatasets, LoadPlugin, Sphere, Triangulate, UpdatePipeline
from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm

import quadcover
from meshchecks import check, check_quads, finish


LoadPlugin(sys.argv[1], remote=False, ns=globals())

# The plugin's filters in pipeline order: paraview.simple's name (its label without spaces) and
# the VTK class.
PROXIES = [
    ("QuadCoverSurfaceRepair", quadcover.vtkQuadCoverSurfaceRepair),
    ("QuadCoverCurvatureFrames", quadcover.vtkCurvatureFrames),
    ("QuadCoverFrameSmoother", quadcover.vtkFrameSmoother),
    ("QuadCoverMatchingBuilder", quadcover.vtkMatchingBuilder),
    ("QuadCoverSolver", quadcover.vtkQuadCoverSolver),
    ("QuadCoverQuadExtractor", quadcover.vtkQuadExtractor),
    ("QuadCoverRemesh", quadcover.vtkQuadCoverRemesh),
]


def the_chain():
    """The five stages after the repair, by their proxies, on a ParaView source."""
    surface = Triangulate(Input=Sphere(ThetaResolution=48, PhiResolution=48))
    stages = [globals()[name] for name, _ in PROXIES[:6]]
    proxy = surface
    for make in stages:
        proxy = make(Input=proxy)
    UpdatePipeline(proxy=proxy)
    quads = servermanager.Fetch(proxy)
    check_quads(quads, "the chain")
    matching = proxy.Input.Input  # extractor <- solver <- matching
    branch = matching.GetClientSideObject().GetOutputDataObject(1)
    check(branch.GetNumberOfPoints() == 8,
          "branch points on port 1: %d, not the sphere's 8" % branch.GetNumberOfPoints())

    remesh = QuadCoverRemesh(Input=surface)  # noqa: F821 (made by LoadPlugin)
    UpdatePipeline(proxy=remesh)
    one_click = servermanager.Fetch(remesh)
    check_quads(one_click, "QuadCoverRemesh")
    check(one_click.GetNumberOfCells() == quads.GetNumberOfCells(),
          "QuadCoverRemesh: %d quads, the chain %d" % (one_click.GetNumberOfCells(),
                                                       quads.GetNumberOfCells()))


def the_blocks():
    """A multiblock of two surfaces: each block remeshed on its own, the structure kept."""
    small = Triangulate(Input=Sphere(Radius=0.2, ThetaResolution=32, PhiResolution=32))
    large = Triangulate(Input=Sphere(Radius=5.0, Center=[20, 0, 0], ThetaResolution=48,
                                     PhiResolution=48))
    group = GroupDatasets(Input=[small, large])
    remesh = QuadCoverRemesh(Input=group)  # noqa: F821 (made by LoadPlugin)
    remesh.TargetQuadCount = 400
    UpdatePipeline(proxy=remesh)
    blocks = servermanager.Fetch(remesh)
    check(blocks.IsA("vtkMultiBlockDataSet") and blocks.GetNumberOfBlocks() == 2,
          "a multiblock of 2 surfaces in, %s of %d blocks out" % (
              blocks.GetClassName(), blocks.GetNumberOfBlocks()))
    for b in range(blocks.GetNumberOfBlocks()):
        block = blocks.GetBlock(b)
        check(block is not None and block.IsA("vtkPolyData"), "block %d is no surface" % b)
        if block is not None and block.IsA("vtkPolyData"):
            check_quads(block, "block %d" % b)
            # each block its own target: the small sphere as many quads as the large one
            check(300 <= block.GetNumberOfCells() <= 520,
                  "block %d: %d quads for a target of 400" % (b, block.GetNumberOfCells()))


def settable(cls):
    """The number and switch properties a filter class adds to vtkPolyDataAlgorithm: a setter
    with a getter of the same name that returns a number or a bool."""
    base = set(dir(vtkPolyDataAlgorithm))
    fresh = cls()
    names = set()
    for m in dir(cls):
        if not m.startswith("Set") or m in base or not hasattr(cls, "Get" + m[3:]):
            continue
        try:
            value = getattr(fresh, "Get" + m[3:])()
        except TypeError:  # a getter that takes arguments
            continue
        if isinstance(value, (bool, int, float)):
            names.add(m[3:])
    return names


def other_value(prop, default):
    """A value in the property's domain other than its default."""
    domain_names = prop.SMProperty.NewDomainIterator()
    domain_names.Begin()
    low = high = None
    entries = []
    while not domain_names.IsAtEnd():
        d = domain_names.GetDomain()
        if d.IsA("vtkSMBooleanDomain"):
            return 0 if default else 1
        if d.IsA("vtkSMEnumerationDomain"):
            entries = [d.GetEntryValue(i) for i in range(d.GetNumberOfEntries())]
        if d.IsA("vtkSMIntRangeDomain") or d.IsA("vtkSMDoubleRangeDomain"):
            if d.GetMinimumExists(0):
                low = d.GetMinimum(0)
            if d.GetMaximumExists(0):
                high = d.GetMaximum(0)
        domain_names.Next()
    if entries:
        return [e for e in entries if e != default][0]
    candidates = [default * 0.5, default + 1, low, high]
    for x in candidates:
        if x is None or x == default:
            continue
        if (low is None or x >= low) and (high is None or x <= high):
            return int(x) if isinstance(default, int) else x
    return None


def the_properties():
    """Every property of every proxy: the XML's default is the filter's, a value set through
    the proxy reaches the VTK object; and every property the class has is in the XML."""
    source = Triangulate(Input=Sphere())
    for name, cls in PROXIES:
        proxy = globals()[name](Input=source)
        vtk_object = proxy.GetClientSideObject()
        check(isinstance(vtk_object, cls), "%s makes a %s" % (name, type(vtk_object).__name__))
        fresh = cls()
        listed = set()
        for prop_name in proxy.ListProperties():
            prop = proxy.GetProperty(prop_name)
            xml_name = prop.SMProperty.GetXMLName()
            getter = getattr(fresh, "Get" + xml_name, None)
            # numbers only: the input and the input-array selections have no getter of their name
            if getter is None or not (prop.SMProperty.IsA("vtkSMIntVectorProperty") or
                                      prop.SMProperty.IsA("vtkSMDoubleVectorProperty")):
                continue
            listed.add(xml_name)
            default = getter()
            xml_default = prop.SMProperty.GetElement(0)  # a new proxy holds the XML's defaults
            check(float(xml_default) == float(default),
                  "%s.%s: XML default %s, the filter's %s" % (name, xml_name, xml_default, default))
            value = other_value(prop, default)
            if value is None:
                check(False, "%s.%s: no value other than the default in its domain" % (name, xml_name))
                continue
            proxy.SetPropertyWithName(xml_name, value)
            proxy.UpdateVTKObjects()
            got = getattr(vtk_object, "Get" + xml_name)()
            check(abs(float(got) - float(value)) <= 1e-12 * max(1.0, abs(float(value))),
                  "%s.%s: set %s, the filter has %s" % (name, xml_name, value, got))
        missing = settable(cls) - listed
        check(not missing, "%s: properties of %s not in the XML: %s" % (
            name, cls.__name__, ", ".join(sorted(missing))))


the_chain()
the_blocks()
the_properties()
finish("plugin")
