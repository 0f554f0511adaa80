// Gmsh meshes of second order (issue 41): 9-node quadrilaterals and 27-node
// hexahedra written by Gmsh 4.8 itself (tests/meshes/*.geo), in formats 2.2
// and 4.1, read with their named groups; their mid-side, face and centre
// nodes give the cells' curved geometry. Against the exact geometry:
// - a quarter annulus (radii 1 and 2; 2-D) and a quarter of a thick
//   cylindrical shell (the annulus extruded by 1; 3-D): the area (volume)
//   3 pi / 4 and the lengths (areas) of the curved surfaces, pi and pi / 2,
//   from the curved cells within 3e-4 (measured 1.6e-4 and 7.7e-5 with
//   three cells along each quarter circle), where the straight cells
//   between the same corners miss by 4.5 % (the ratio must exceed 100;
//   measured 290);
// - every node of a face of the surfaces 'outer' and 'inner' is on its
//   circle to 1e-8 (measured 4e-16; a node given to the wrong edge or face
//   of a cell is off by 0.1 or more);
// - the area error of the curved cells falls by at least 2^3.5 from the
//   coarse to the twice finer annulus (an isoparametric arc of degree 2
//   converges as h^4; measured 3.99);
// - refining the mesh twice keeps the area to 1e-12: refined cells are
//   parts of their coarse cell's map, not chords of it;
// - formats 2.2 and 4.1 give the same geometry to 1e-14.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <contact_dynamics/mechanics/geometry_mapping.h>

#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  const std::string meshes = std::string(SOURCE_DIR) + "/meshes/";

  struct Measures
  {
    double              volume = 0;
    std::vector<double> surfaces; // per boundary id
    double              node_off_circle = 0;
  };

  // radius in the x-y plane
  template <int dim>
  double
  radius(const Point<dim> &p)
  {
    return std::hypot(p[0], p[1]);
  }

  template <int dim>
  Measures
  measure(const Triangulation<dim>           &tria,
          const Mapping<dim>                 &mapping,
          const ContactDynamics::SceneLayout &layout)
  {
    Measures          m;
    const FE_Q<dim>   fe(1);
    const QGauss<dim> q(5);
    FEValues<dim>     fe_values(mapping, fe, q, update_JxW_values);
    FEFaceValues<dim> face_values(mapping,
                                  fe,
                                  QGauss<dim - 1>(5),
                                  update_JxW_values);
    // the faces' nodes: FE_Q(2)'s support points on the face
    const FE_Q<dim>   q2(2);
    FEFaceValues<dim> node_values(mapping,
                                  q2,
                                  Quadrature<dim - 1>(
                                    FE_Q<dim - 1>(2).get_unit_support_points()),
                                  update_quadrature_points);
    m.surfaces.assign(layout.surfaces.size(), 0.);
    const auto outer = layout.surface_id("outer");
    const auto inner = layout.surface_id("inner");
    for (const auto &cell : tria.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (unsigned int k = 0; k < q.size(); ++k)
          m.volume += fe_values.JxW(k);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = cell->face(f)->boundary_id();
              face_values.reinit(cell, f);
              for (unsigned int k = 0; k < face_values.n_quadrature_points; ++k)
                m.surfaces[id] += face_values.JxW(k);
              if (cell->level() > 0 || (id != outer && id != inner))
                continue;
              node_values.reinit(cell, f);
              for (const auto &p : node_values.get_quadrature_points())
                m.node_off_circle =
                  std::max(m.node_off_circle,
                           std::abs(radius(p) - (id == outer ? 2. : 1.)));
            }
      }
    return m;
  }

  template <int dim>
  ContactDynamics::Scene<dim>
  gmsh_scene(const std::string &file)
  {
    return make_scene<dim>("gmsh", 1, [&](ParameterHandler &prm) {
      prm.set("Mesh file", meshes + file);
    });
  }

  // Returns the relative volume error of the curved cells.
  template <int dim>
  double
  check_file(const std::string &file, const double reference_volume = 0)
  {
    const std::string name   = file + ": ";
    const auto        scene  = gmsh_scene<dim>(file);
    const auto        layout = scene.layout();
    deallog << name << "body " << layout.body_names[0] << ", surfaces";
    for (const auto &[surface, id] : layout.surfaces)
      deallog << ' ' << surface;
    deallog << std::endl;

    Triangulation<dim> tria;
    scene.create_triangulation(tria);
    const auto geometry = scene.cell_geometry();
    check_true(name + "geometry from the nodes", geometry != nullptr);
    ContactDynamics::GeometryMapping<dim> curved;
    curved.set_geometry(geometry);
    const MappingQ<dim> straight(1);

    const double   exact_volume = 3 * numbers::PI / 4;
    const Measures m            = measure(tria, curved, layout);
    const Measures chords       = measure(tria, straight, layout);
    const double   error        = std::abs(m.volume / exact_volume - 1);
    const auto     outer        = layout.surface_id("outer");
    const auto     inner        = layout.surface_id("inner");
    check_range(name + "|volume / (3 pi / 4) - 1|", error, 0, 3e-4);
    check_range(name + "|outer / pi - 1|",
                std::abs(m.surfaces[outer] / numbers::PI - 1),
                0,
                3e-4);
    check_range(name + "|inner / (pi / 2) - 1|",
                std::abs(m.surfaces[inner] / (numbers::PI / 2) - 1),
                0,
                3e-4);
    check_range(name + "straight cells' volume error / curved cells'",
                std::abs(chords.volume / exact_volume - 1) / error,
                100,
                1e12);
    check_range(name + "nodes of the curved surfaces off their circle",
                m.node_off_circle,
                0,
                1e-8);
    if (reference_volume > 0)
      check_close(name + "volume / format 2.2's - 1",
                  m.volume / reference_volume - 1,
                  0,
                  1e-14);

    tria.refine_global(2);
    const Measures refined = measure(tria, curved, layout);
    check_close(name + "refined twice: volume / coarse volume - 1",
                refined.volume / m.volume - 1,
                0,
                1e-12);
    return m.volume;
  }
} // namespace

int
main()
{
  initlog();
  const double annulus = check_file<2>("quarter_annulus_order2.msh");
  check_file<2>("quarter_annulus_order2_v41.msh", annulus);
  const double shell = check_file<3>("cylindrical_shell_order2.msh");
  check_file<3>("cylindrical_shell_order2_v41.msh", shell);

  const double exact = 3 * numbers::PI / 4;
  const double fine  = check_file<2>("quarter_annulus_order2_fine.msh");
  check_range("annulus: observed order of the area error, h to h/2",
              std::log2(std::abs(annulus / exact - 1) /
                        std::abs(fine / exact - 1)),
              3.5,
              6);
}
