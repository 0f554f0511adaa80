// ContactSurface<3>: the faces of a 3-D mesh's boundary as bilinear
// quadrilaterals with outward normals (x1 - x0) x (x2 - x0), against what
// the mesh says independently:
// 1. the top and bottom of a 2 x 3 x 1 box: 12 nodes and 6 faces each,
//    normals +z and -z, nodal weights integral N_j = a quarter of each
//    adjacent face's area (corners 0.25, interior nodes 1), summing to 6;
// 2. every face of a sheared, rotated cube with 3 x 3 x 3 cells: each face
//    normal points away from the cube's center, and the weights sum to the
//    sum of deal.II's face measures (planar faces: exact);
// 3. the R-tree search on 3-D face boxes: the candidates of the box's top
//    faces among the bottom faces of a finer, rotated box above it, with
//    the boxes enlarged by the gap, are the pairs whose boxes overlap by a
//    brute-force comparison of all pairs.
#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/trilinos_vector.h>

#include <contact_dynamics/contact/contact_search.h>
#include <contact_dynamics/contact/contact_surface.h>

#include "tests.h"

#include <deal.II/distributed/shared_tria.h>

using namespace dealii;
using ContactDynamics::ContactSurface;

namespace
{
  Tensor<1, 3>
  face_normal(const ContactSurface<3> &s, const unsigned int f)
  {
    const auto &x = s.reference;
    const auto &n = s.faces[f];
    return cross_product_3d(x[n[1]] - x[n[0]], x[n[2]] - x[n[0]]);
  }
} // namespace

int
main()
{
  initlog();
  const FESystem<3> fe(FE_Q<3>(1), 3);

  // 1. the box
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {2, 3, 1},
                                              Point<3>(0, 0, 0),
                                              Point<3>(2, 3, 0.5),
                                              true);
    DoFHandler<3> dofs(tria);
    dofs.distribute_dofs(fe);
    for (const types::boundary_id id : {4, 5})
      {
        ContactSurface<3> surface;
        surface.build(dofs, {id}, 3);
        const std::string name = id == 5 ? "top" : "bottom";
        check_true(name + ": 12 nodes, 6 faces",
                   surface.n_nodes() == 12 && surface.n_faces() == 6);
        double worst = 1;
        for (unsigned int f = 0; f < surface.n_faces(); ++f)
          {
            const Tensor<1, 3> n = face_normal(surface, f);
            worst = std::min(worst, (id == 5 ? 1. : -1.) * n[2] / n.norm());
          }
        check_close(name + ": normals outward", worst, 1, 1e-14);
        double total = 0, weights_error = 0;
        for (unsigned int j = 0; j < surface.n_nodes(); ++j)
          {
            total += surface.reference_weight[j];
            // a quarter of each adjacent unit face
            weights_error =
              std::max(weights_error,
                       std::abs(surface.reference_weight[j] -
                                0.25 * surface.node_faces[j].size()));
          }
        check_close(name + ": weights sum to the area", total, 6, 1e-13);
        check_close(name + ": each node a quarter of its faces",
                    weights_error,
                    0,
                    1e-14);
        bool dofs_ok = true;
        for (const auto &d : surface.dofs)
          dofs_ok = dofs_ok && d.size() == 3;
        check_true(name + ": three dofs per node", dofs_ok);
      }
  }

  // 2. the sheared, rotated cube, all six sides
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_cube(tria, 3, 0, 1, true);
    GridTools::transform(
      [](const Point<3> &p) {
        return Point<3>(p[0] + 0.3 * p[1],
                        p[1] + 0.2 * p[2],
                        p[2] + 0.1 * p[0]);
      },
      tria);
    GridTools::rotate(Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.), 0.7, tria);
    Point<3> center;
    for (const auto &v : tria.get_vertices())
      center += v / double(tria.n_vertices());
    DoFHandler<3> dofs(tria);
    dofs.distribute_dofs(fe);
    ContactSurface<3> surface;
    surface.build(dofs, {0, 1, 2, 3, 4, 5}, 3);
    double measure = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          measure += face->measure();
    check_true("cube: 54 faces, 56 nodes",
               surface.n_faces() == 54 && surface.n_nodes() == 56);
    bool outward = true;
    for (unsigned int f = 0; f < surface.n_faces(); ++f)
      {
        Point<3> face_center;
        for (const unsigned int v : surface.faces[f])
          face_center += surface.reference[v] / 4.;
        outward =
          outward && face_normal(surface, f) * (face_center - center) > 0;
      }
    check_true("cube: every normal points away from the center", outward);
    double total = 0;
    for (const double w : surface.reference_weight)
      total += w;
    check_close("cube: weights sum to the faces' measures",
                total / measure,
                1,
                1e-13);
  }

  // 3. search
  {
    Triangulation<3> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower,
                                              {4, 4, 1},
                                              Point<3>(0, 0, 0),
                                              Point<3>(2, 2, 0.5),
                                              true);
    GridGenerator::subdivided_hyper_rectangle(upper,
                                              {7, 5, 1},
                                              Point<3>(0.6, 0.3, 0.55),
                                              Point<3>(1.6, 1.3, 1),
                                              true);
    GridTools::rotate(Tensor<1, 3>({0., 0., 1.}), 0.3, upper);
    DoFHandler<3> lower_dofs(lower), upper_dofs(upper);
    lower_dofs.distribute_dofs(fe);
    upper_dofs.distribute_dofs(fe);
    ContactSurface<3> secondary, primary;
    secondary.build(lower_dofs, {5}, 3);
    primary.build(upper_dofs, {4}, 3);
    const TrilinosWrappers::MPI::Vector u_s(complete_index_set(
                                              lower_dofs.n_dofs()),
                                            MPI_COMM_WORLD),
      u_p(complete_index_set(upper_dofs.n_dofs()), MPI_COMM_WORLD);
    std::vector<BoundingBox<3>> s_boxes, p_boxes;
    double                      size;
    for (unsigned int f = 0; f < secondary.n_faces(); ++f)
      {
        s_boxes.push_back(secondary.face_box(f, u_s, size));
        s_boxes.back().extend(0.06);
      }
    for (unsigned int f = 0; f < primary.n_faces(); ++f)
      p_boxes.push_back(primary.face_box(f, u_p, size));
    const auto candidates =
      ContactDynamics::find_candidate_pairs(s_boxes, p_boxes);
    bool         same    = true;
    unsigned int n_pairs = 0, without = 0;
    for (unsigned int i = 0; i < s_boxes.size(); ++i)
      {
        std::vector<unsigned int> expected;
        for (unsigned int j = 0; j < p_boxes.size(); ++j)
          {
            bool overlap = true;
            for (unsigned int d = 0; d < 3; ++d)
              overlap =
                overlap &&
                s_boxes[i].lower_bound(d) <= p_boxes[j].upper_bound(d) &&
                p_boxes[j].lower_bound(d) <= s_boxes[i].upper_bound(d);
            if (overlap)
              expected.push_back(j);
          }
        same = same && expected == candidates[i];
        n_pairs += expected.size();
        without += expected.empty();
      }
    check_true("search: the R-tree's candidates are the overlapping pairs",
               same);
    check_true("search: some faces have candidates, some none",
               n_pairs > 0 && without > 0);
  }
}
