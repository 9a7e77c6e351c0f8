#!/usr/bin/env python3
"""Per-frame timing of ParaView's Surface LIC (VTK's vtkSurfaceLICMapper).

ParaView's "Surface LIC" representation is a thin wrapper around VTK's
vtkSurfaceLICMapper / vtkSurfaceLICInterface (module vtkRenderingLICOpenGL2).
This script drives that mapper directly through the VTK Python modules that
ship inside Debian's python3-paraview package (run it through run.sh, which
sets PYTHONPATH and starts Xvfb).

Scene: a UV sphere of radius 1 with about N triangles (vtkSphereSource),
point normals, and a point vector array "velocity" = w x p with
w = normalize(0.3, 1, 0.2) (solid-body rotation, tangential to the sphere).

Timing: for every (triangles, image size, steps) configuration one warm-up
frame is rendered, then K frames, each after a 0.5 degree camera azimuth
change, so that the surface LIC pipeline (vector projection, LIC, shading) is
recomputed on every frame.  Each frame is Render() followed by a read-back of
the whole RGBA image with vtkRenderWindow::GetRGBACharPixelData (glReadPixels),
which forces the GL pipeline to finish.  The read-back is included in the time.
"""

import argparse
import csv
import json
import math
import os
import sys
import time


def parse_int_list(text):
    return [int(float(x)) for x in text.split(",") if x.strip()]


def parse_sizes(text):
    sizes = []
    for item in text.split(","):
        item = item.strip().lower()
        if not item:
            continue
        w, h = item.split("x")
        sizes.append((int(w), int(h)))
    return sizes


def sphere_resolution(n_triangles):
    """Theta/phi resolution of vtkSphereSource giving about n triangles.

    vtkSphereSource (full sphere, LatLongTessellation off) makes
    2*theta*(phi-2) triangles: phi counts the two pole points, so there are
    phi-2 latitude rings, theta triangles in each pole cap and
    2*theta*(phi-3) in the bands between rings.  Keep theta ~ 2*(phi-1)
    (roughly square cells at the equator).
    """
    best = None
    p0 = max(3, int(round(math.sqrt(n_triangles / 4.0))) + 2)
    for phi in range(max(3, p0 - 3), p0 + 4):
        for theta in range(max(3, 2 * (phi - 1) - 6), 2 * (phi - 1) + 7):
            tris = 2 * theta * (phi - 2)
            key = (abs(tris - n_triangles), abs(theta - 2 * (phi - 1)))
            if best is None or key < best[0]:
                best = (key, theta, phi, tris)
    return best[1], best[2], best[3]


def build_sphere(n_triangles):
    import numpy as np
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    theta, phi, _ = sphere_resolution(n_triangles)
    src = vtkSphereSource()
    src.SetRadius(1.0)
    src.SetCenter(0.0, 0.0, 0.0)
    src.SetThetaResolution(theta)
    src.SetPhiResolution(phi)
    src.LatLongTessellationOff()
    src.Update()

    normals = vtkPolyDataNormals()
    normals.SetInputConnection(src.GetOutputPort())
    normals.ComputePointNormalsOn()
    normals.ComputeCellNormalsOff()
    normals.SplittingOff()          # keep one normal per point, no seams
    normals.ConsistencyOn()
    normals.AutoOrientNormalsOn()   # outward on a closed surface
    normals.Update()

    poly = normals.GetOutput()
    pts = vtk_to_numpy(poly.GetPoints().GetData()).astype(np.float64)
    w = np.array([0.3, 1.0, 0.2])
    w /= np.linalg.norm(w)
    vel = np.cross(np.broadcast_to(w, pts.shape), pts).astype(np.float32)
    arr = numpy_to_vtk(np.ascontiguousarray(vel), deep=1)
    arr.SetName("velocity")
    poly.GetPointData().AddArray(arr)
    poly.GetPointData().SetActiveVectors("velocity")
    return poly, theta, phi


def read_mesh(path, field):
    """A surface file (any VTK XML/legacy PolyData) triangulated, with point normals and
    `field` as the active point vectors."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.vtkIOLegacy import vtkPolyDataReader
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals, vtkTriangleFilter

    reader = vtkXMLPolyDataReader() if path.endswith(".vtp") else vtkPolyDataReader()
    reader.SetFileName(path)
    tri = vtkTriangleFilter()
    tri.SetInputConnection(reader.GetOutputPort())
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(tri.GetOutputPort())
    normals.ComputePointNormalsOn()
    normals.SplittingOff()
    normals.Update()
    poly = normals.GetOutput()
    if poly.GetPointData().GetArray(field) is None:
        raise SystemExit("%s has no point array %r" % (path, field))
    poly.GetPointData().SetActiveVectors(field)
    return poly


def step_size_for(step_px, width, height, mode):
    """LIC StepSize argument for a wanted on-screen step of step_px pixels.

    vtkSurfaceLICInterface documents StepSize as "in pixels", but converts it
    to texture units as StepSize*sqrt(1/W^2 + 1/H^2) and integrates with
    normalized vectors in texture space, so one step actually moves
    StepSize*sqrt(1 + (W/H)^2) pixels horizontally and
    StepSize*sqrt(1 + (H/W)^2) pixels vertically (sqrt(2)*StepSize on a square
    viewport).  mode 'api' passes step_px through unchanged (the documented
    unit); mode 'screen' divides by the geometric mean of those two factors
    so that a step is about step_px real pixels.
    """
    if mode == "api":
        return step_px
    r = float(width) / float(height)
    fx = math.sqrt(1.0 + r * r)
    fy = math.sqrt(1.0 + 1.0 / (r * r))
    return step_px / math.sqrt(fx * fy)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--triangles", default="10000,80000,220000,1000000",
                    help="comma list of approximate triangle counts")
    ap.add_argument("--sizes", default="512x512,1024x1024,1920x1080",
                    help="comma list of WxH image sizes")
    ap.add_argument("--steps", default="10,25,50,100",
                    help="comma list of LIC NumberOfSteps (each direction)")
    ap.add_argument("--frames", type=int, default=5,
                    help="timed frames per configuration (K)")
    ap.add_argument("--azimuth", type=float, default=0.5,
                    help="camera azimuth change in degrees before each frame")
    ap.add_argument("--step-px", type=float, default=2.0,
                    help="wanted LIC integration step length in pixels")
    ap.add_argument("--step-mode", choices=["screen", "api"], default="screen",
                    help="'screen': StepSize chosen so a step is about step-px real "
                         "pixels; 'api': SetStepSize(step-px) as documented")
    ap.add_argument("--enhanced-lic", type=int, choices=[0, 1], default=0,
                    help="vtkSurfaceLICInterface EnhancedLIC (second LIC pass on an "
                         "edge-enhanced first pass). VTK/ParaView default is 1; "
                         "default here is 0 = one LIC pass")
    ap.add_argument("--csv", default=None, help="write results to this CSV file")
    ap.add_argument("--images", default=None,
                    help="folder for one PNG per mesh/size (first steps value)")
    ap.add_argument("--static-check", action="store_true",
                    help="also time K frames without camera change (ms_static column, stdout "
                         "only): shows whether VTK reuses the previous LIC")
    ap.add_argument("--mesh", default=None,
                    help="time this surface file (PolyData) instead of the spheres of --triangles")
    ap.add_argument("--field", default="velocity", help="the point vector array of --mesh")
    ap.add_argument("--camera-json", default=None,
                    help="camera of the first frame (JSON eye, target, up, fov: as written by "
                         "hybrid_file_bench.py) instead of ResetCamera from (0.3, 0.4, 1)")
    ap.add_argument("--quiet-vtk", action="store_true",
                    help="silence VTK warnings in the output window")
    args = ap.parse_args()

    from vtkmodules.vtkCommonCore import vtkVersion, vtkUnsignedCharArray, vtkOutputWindow
    from vtkmodules.vtkCommonDataModel import vtkDataObject
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderer, vtkRenderWindow,
                                             vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers GL factories)
    from vtkmodules.vtkRenderingLICOpenGL2 import vtkSurfaceLICMapper, vtkSurfaceLICInterface
    from vtkmodules.vtkIOImage import vtkPNGWriter

    if args.quiet_vtk:
        vtkOutputWindow.GetInstance().SetDisplayModeToNever()

    tri_list = [0] if args.mesh else parse_int_list(args.triangles)
    sizes = parse_sizes(args.sizes)
    steps_list = parse_int_list(args.steps)

    if args.images:
        os.makedirs(args.images, exist_ok=True)

    ren_win = vtkRenderWindow()
    ren_win.SetMultiSamples(0)
    ren_win.SetSize(*sizes[0])
    ren = vtkRenderer()
    ren.SetBackground(0.1, 0.1, 0.15)
    ren_win.AddRenderer(ren)
    ren_win.Render()

    caps = ren_win.ReportCapabilities() or ""
    gl_lines = [l.strip() for l in caps.splitlines()
                if l.strip().startswith(("OpenGL vendor", "OpenGL renderer", "OpenGL version"))]
    print("# VTK %s (from %s)" % (vtkVersion.GetVTKVersion(),
                                  os.path.dirname(vtkmodules.vtkRenderingOpenGL2.__file__)))
    print("# render window: %s" % ren_win.GetClassName())
    for l in gl_lines:
        print("# " + l)
    print("# LP_NUM_THREADS=%s  nproc=%d  loadavg(1,5,15 min) at start: %.2f %.2f %.2f"
          % ((os.environ.get("LP_NUM_THREADS", "(unset)"), os.cpu_count() or 0)
             + tuple(os.getloadavg())))
    if not vtkSurfaceLICInterface.IsSupported(ren_win):
        print("ERROR: surface LIC not supported by this GL context", file=sys.stderr)
        return 2
    print("# EnhancedLIC=%d NormalizeVectors=1 EnhanceContrast=OFF AntiAlias=0 "
          "step-px=%.3g step-mode=%s frames=%d azimuth=%.2fdeg"
          % (args.enhanced_lic, args.step_px, args.step_mode, args.frames, args.azimuth))
    sys.stdout.flush()

    rows = []
    header = "%10s %6s %6s %6s %9s %12s %8s" % ("triangles", "width", "height", "steps",
                                                "StepSize", "ms_per_frame", "min_ms")
    if args.static_check:
        header += " %13s" % "ms_static"
    print(header)
    sys.stdout.flush()

    pixels = vtkUnsignedCharArray()

    for n_req in tri_list:
        t0 = time.perf_counter()
        if args.mesh:
            poly, field = read_mesh(args.mesh, args.field), args.field
            print("# mesh: %s, field %s, %d triangles, %d points" % (args.mesh, field, poly.GetNumberOfCells(),
                                                                     poly.GetNumberOfPoints()))
        else:
            poly, theta, phi = build_sphere(n_req)
            field = "velocity"
            print("# mesh: requested %d -> theta=%d phi=%d -> %d triangles, %d points (%.2fs)"
                  % (n_req, theta, phi, poly.GetNumberOfCells(), poly.GetNumberOfPoints(),
                     time.perf_counter() - t0))
        n_tris = poly.GetNumberOfCells()
        sys.stdout.flush()

        mapper = vtkSurfaceLICMapper()
        mapper.SetInputData(poly)
        mapper.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS,
                                      field)
        mapper.ScalarVisibilityOff()
        lic = mapper.GetLICInterface()
        lic.SetNormalizeVectors(1)
        lic.SetEnhanceContrast(vtkSurfaceLICInterface.ENHANCE_CONTRAST_OFF)
        lic.SetEnhancedLIC(args.enhanced_lic)
        lic.SetAntiAlias(0)
        lic.SetColorMode(vtkSurfaceLICInterface.COLOR_MODE_BLEND)
        lic.SetLICIntensity(0.8)

        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(1.0, 1.0, 1.0)
        ren.AddActor(actor)

        for (w, h) in sizes:
            ren_win.SetSize(w, h)
            for si, steps in enumerate(steps_list):
                step_size = step_size_for(args.step_px, w, h, args.step_mode)
                lic.SetNumberOfSteps(steps)
                lic.SetStepSize(step_size)

                cam = ren.GetActiveCamera()
                if args.camera_json:
                    with open(args.camera_json) as f:
                        c = json.load(f)
                    cam.SetFocalPoint(*c["target"])
                    cam.SetPosition(*c["eye"])
                    cam.SetViewUp(*c["up"])
                    cam.SetViewAngle(c["fov"])
                    cam.OrthogonalizeViewUp()
                else:  # camera fitted to the sphere, looking from direction (0.3, 0.4, 1)
                    d = (0.3, 0.4, 1.0)
                    nd = math.sqrt(sum(c * c for c in d))
                    cam.SetFocalPoint(0.0, 0.0, 0.0)
                    cam.SetPosition(*(5.0 * c / nd for c in d))
                    cam.SetViewUp(0.0, 1.0, 0.0)
                    ren.ResetCamera()
                ren.ResetCameraClippingRange()

                # warm-up frame (shader compilation, texture allocation)
                ren_win.Render()
                ren_win.GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels)

                if args.images and si == 0:
                    w2i = vtkWindowToImageFilter()
                    w2i.SetInput(ren_win)
                    w2i.ReadFrontBufferOff()
                    w2i.ShouldRerenderOff()
                    w2i.Update()
                    png = vtkPNGWriter()
                    fn = os.path.join(args.images, "surface_lic_%dtri_%dx%d_steps%d.png"
                                      % (n_tris, w, h, steps))
                    png.SetFileName(fn)
                    png.SetInputConnection(w2i.GetOutputPort())
                    png.Write()

                times = []
                cpu0 = time.process_time()  # all threads of this process (llvmpipe's included)
                for _ in range(args.frames):
                    cam.Azimuth(args.azimuth)
                    ren.ResetCameraClippingRange()
                    t0 = time.perf_counter()
                    ren_win.Render()
                    ren_win.GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels)
                    times.append(time.perf_counter() - t0)
                ms = 1000.0 * sum(times) / len(times)
                cpu_ms = 1000.0 * (time.process_time() - cpu0) / args.frames

                line = "%10d %6d %6d %6d %9.4f %12.1f %8.1f" % (n_tris, w, h, steps, step_size,
                                                               ms, 1000.0 * min(times))
                if args.static_check:
                    st = []
                    for _ in range(args.frames):
                        t0 = time.perf_counter()
                        ren_win.Render()
                        ren_win.GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels)
                        st.append(time.perf_counter() - t0)
                    line += " %13.1f" % (1000.0 * sum(st) / len(st))
                print(line)
                sys.stdout.flush()
                rows.append((n_tris, w, h, steps, round(ms, 2), round(cpu_ms, 2)))
                if args.csv:  # rewrite after every row so partial runs keep data
                    with open(args.csv, "w", newline="") as f:
                        wr = csv.writer(f)
                        wr.writerow(["triangles", "width", "height", "steps", "ms_per_frame", "cpu_ms_per_frame"])
                        wr.writerows(rows)

        ren.RemoveActor(actor)
        mapper.ReleaseGraphicsResources(ren_win)
        del actor, mapper, poly

    print("# loadavg(1,5,15 min) at end: %.2f %.2f %.2f" % tuple(os.getloadavg()))
    ren_win.Finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
