/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the shape templates of atom_style polyhedron on the device,
   for the /kk styles (pair polyhedron/kk, ellipsoid/kk, fix wall/mesh/kk):
   every template's vertices, planes, face loops, edges and int arrays (dual
   seed, vertex adjacency) flat in a few Views, one ShapeView per template
   whose pointers address them, and the semi-axes of ellipsoid templates.
   The parts of composite templates follow the templates (views n, n+1, ...)
   and each composite's ShapePart entries point to them.
   Uploaded again only when the library's shape version changes.
------------------------------------------------------------------------- */

#ifndef POLYDEM_SHAPES_KOKKOS_H
#define POLYDEM_SHAPES_KOKKOS_H

#include "poly_shape_library.h"
#include "polydem_shape_template.h"
#include "polydem_shape_view.h"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace polydem_kk {

template <class DeviceType> struct DeviceShapes {
  int version = -1;      // the library's shape version uploaded, -1: none
  int max_faces = 0;     // largest face count of the templates
  Kokkos::View<double *, DeviceType> verts, planes;
  Kokkos::View<int *, DeviceType> face_start, face_verts, edges;
  Kokkos::View<int *, DeviceType> ints;    // per template: dual seed (with_dual), vertex adjacency
  Kokkos::View<polydem::ShapeView<double> *, DeviceType> views;
  Kokkos::View<polydem::ShapePart<double> *, DeviceType> parts;    // of the composites
  Kokkos::View<double *[3], DeviceType> axes;    // semi-axes of ellipsoid templates, else 0

  // upload if the library changed; with_dual: also the dual seeds (the
  // overlap kernel's), else ShapeView::dual is null. Returns true if it did.
  bool update(const LAMMPS_NS::PolyShapeLibrary &lib, bool with_dual, const std::string &label)
  {
    if (version == lib.shape_version()) return false;
    const int n = lib.ntemplates();
    // every template, then the parts of the composites (views n, n+1, ...)
    std::vector<const polydem::PolyShapeTemplate *> all;
    for (int t = 0; t < n; t++) all.push_back(&lib.shape(t));
    int nparts = 0;
    for (int t = 0; t < n; t++)
      for (int k = 0; k < lib.shape(t).nparts(); k++) {
        all.push_back(&lib.shape(t).part_shape(k));
        nparts++;
      }
    const int nall = (int) all.size();
    enum { VERTS, PLANES, FSTART, FVERTS, EDGES, DUAL, VADJ, NARRAY };
    auto sizes = [&](const polydem::ShapeView<double> &sv, int *add) {
      add[VERTS] = 3 * sv.nverts;
      add[PLANES] = 4 * sv.nfaces;
      add[FSTART] = sv.nfaces + 1;
      add[FVERTS] = sv.face_start[sv.nfaces];
      add[EDGES] = 2 * sv.nedges;
      add[DUAL] = with_dual ? polydem::dual_seed_ints(sv) : 0;
      add[VADJ] = polydem::vertex_adjacency_ints(sv);
    };
    int size[NARRAY] = {0, 0, 0, 0, 0, 0, 0}, add[NARRAY];
    max_faces = 0;
    for (int t = 0; t < nall; t++) {
      const auto sv = all[t]->view();
      sizes(sv, add);
      for (int k = 0; k < NARRAY; k++) size[k] += add[k];
      max_faces = std::max(max_faces, sv.nfaces);
    }
    const int m = nall > 0 ? nall : 1;
    verts = Kokkos::View<double *, DeviceType>(label + ":verts", size[VERTS]);
    planes = Kokkos::View<double *, DeviceType>(label + ":planes", size[PLANES]);
    face_start = Kokkos::View<int *, DeviceType>(label + ":face_start", size[FSTART]);
    face_verts = Kokkos::View<int *, DeviceType>(label + ":face_verts", size[FVERTS]);
    edges = Kokkos::View<int *, DeviceType>(label + ":edges", size[EDGES]);
    ints = Kokkos::View<int *, DeviceType>(label + ":dual_vadj", size[DUAL] + size[VADJ]);
    views = Kokkos::View<polydem::ShapeView<double> *, DeviceType>(label + ":shapes", m);
    parts = Kokkos::View<polydem::ShapePart<double> *, DeviceType>(label + ":parts",
                                                                    nparts > 0 ? nparts : 1);
    axes = Kokkos::View<double *[3], DeviceType>(label + ":axes", m);
    auto h_verts = Kokkos::create_mirror_view(verts);
    auto h_planes = Kokkos::create_mirror_view(planes);
    auto h_fs = Kokkos::create_mirror_view(face_start);
    auto h_fv = Kokkos::create_mirror_view(face_verts);
    auto h_edges = Kokkos::create_mirror_view(edges);
    auto h_ints = Kokkos::create_mirror_view(ints);
    auto h_views = Kokkos::create_mirror_view(views);
    auto h_parts = Kokkos::create_mirror_view(parts);
    auto h_axes = Kokkos::create_mirror_view(axes);
    int off[NARRAY] = {0, 0, 0, 0, 0, 0, 0};
    int iints = 0;    // the dual seed and the adjacency of a template, in one int array
    int ipart = 0;    // next part, in the order of the views n, n+1, ...
    for (int t = 0; t < nall; t++) {
      const auto &shape = *all[t];
      const auto sv = shape.view();
      sizes(sv, add);
      for (int k = 0; k < add[VERTS]; k++) h_verts(off[VERTS] + k) = sv.verts[k];
      for (int k = 0; k < add[PLANES]; k++) h_planes(off[PLANES] + k) = sv.planes[k];
      for (int k = 0; k < add[FSTART]; k++) h_fs(off[FSTART] + k) = sv.face_start[k];
      for (int k = 0; k < add[FVERTS]; k++) h_fv(off[FVERTS] + k) = sv.face_verts[k];
      for (int k = 0; k < add[EDGES]; k++) h_edges(off[EDGES] + k) = sv.edges[k];
      for (int k = 0; k < add[DUAL]; k++) h_ints(iints + k) = sv.dual[k];
      for (int k = 0; k < add[VADJ]; k++) h_ints(iints + add[DUAL] + k) = sv.vadj[k];
      polydem::ShapeView<double> dv = sv;    // counts, radius, volume, inertia
      dv.verts = verts.data() + off[VERTS];
      dv.planes = planes.data() + off[PLANES];
      dv.face_start = face_start.data() + off[FSTART];
      dv.face_verts = face_verts.data() + off[FVERTS];
      dv.edges = edges.data() + off[EDGES];
      dv.dual = add[DUAL] > 0 ? ints.data() + iints : nullptr;
      dv.vadj = add[VADJ] > 0 ? ints.data() + iints + add[DUAL] : nullptr;
      if (sv.nparts > 0) {    // its parts' placements, their views on the device
        dv.parts = parts.data() + ipart;
        for (int k = 0; k < sv.nparts; k++) {
          polydem::ShapePart<double> p = sv.parts[k];
          p.view = views.data() + n + ipart;
          h_parts(ipart++) = p;
        }
      }
      h_views(t) = dv;
      for (int k = 0; k < 3; k++) h_axes(t, k) = shape.is_ellipsoid() ? shape.semi_axes()[k] : 0.0;
      for (int k = 0; k < NARRAY; k++) off[k] += add[k];
      iints += add[DUAL] + add[VADJ];
    }
    Kokkos::deep_copy(verts, h_verts);
    Kokkos::deep_copy(planes, h_planes);
    Kokkos::deep_copy(face_start, h_fs);
    Kokkos::deep_copy(face_verts, h_fv);
    Kokkos::deep_copy(edges, h_edges);
    Kokkos::deep_copy(ints, h_ints);
    Kokkos::deep_copy(views, h_views);
    Kokkos::deep_copy(parts, h_parts);
    Kokkos::deep_copy(axes, h_axes);
    version = lib.shape_version();
    return true;
  }

  double memory_usage() const
  {
    return (double) (verts.extent(0) + planes.extent(0) + 3 * axes.extent(0)) * sizeof(double) +
        (double) (face_start.extent(0) + face_verts.extent(0) + edges.extent(0) +
                  ints.extent(0)) * sizeof(int) +
        (double) views.extent(0) * sizeof(polydem::ShapeView<double>) +
        (double) parts.extent(0) * sizeof(polydem::ShapePart<double>);
  }
};

}    // namespace polydem_kk

#endif
