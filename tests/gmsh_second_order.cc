// Gmsh meshes of second order (issue 41): 9-node quadrilaterals and 27-node
// hexahedra written by Gmsh 4.8 itself (tests/meshes/*.geo), in formats 2.2
// and 4.1, read with their named groups; their mid-side, face and centre
// nodes give the cells' curved geometry. Against the exact geometry:
// - a quarter annulus (radii 1 and 2; 2-D) and a quarter of a thick
//   cylindrical shell (the annulus extruded by 1; 3-D), structured: the
//   area (volume) 3 pi / 4 and the lengths (areas) of the curved surfaces,
//   pi and pi / 2, from the curved cells within 3e-4 (measured 1.6e-4 and
//   7.7e-5 with three cells along each quarter circle), where the straight
//   cells between the same corners miss by 4.5 % (the ratio must exceed
//   100; measured 290);
// - unstructured meshes, whose cells GridIn turns and renumbers: a disc
//   (R = 1) whose cells are all numbered clockwise in the file, and a ball
//   (R = 1, format 4.1, tetrahedra split into hexahedra, some of whose
//   chords fold where the curved cells do not): area pi and rim 2 pi
//   within 1e-4 (measured 3.1e-6, 1.5e-6), volume 4 pi / 3 and surface
//   4 pi within 1e-3 (measured 1.3e-4, 8.8e-5), the straight cells 2000
//   and 430 times farther off;
// - every node of a face on a curved surface is on its circle or sphere to
//   1e-8 (measured 4e-16 and below; a node given to the wrong edge or face
//   of a cell is off by 0.01 or more);
// - the unit cube in unstructured hexahedra: its cells are trilinear, so
//   the curved mapping must be MappingQ1's to 1e-12 at every quadrature
//   point and the volume 1 to 1e-12;
// - the area error of the curved cells falls by at least 2^3.5 from the
//   coarse to the twice finer annulus (an isoparametric arc of degree 2
//   converges as h^4; measured 3.99);
// - refining the mesh twice keeps the area to 1e-12: refined cells are
//   parts of their coarse cell's map, not chords of it;
// - formats 2.2 and 4.1, 4.1 with parametric coordinates and 2.2 with
//   Windows line ends give the same geometry to 1e-14.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <contact_dynamics/mechanics/geometry_mapping.h>

#include "tests.h"

#include <cmath>
#include <fstream>

using namespace dealii;

namespace
{
  const std::string meshes = std::string(SOURCE_DIR) + "/meshes/";

  // A body's exact measures: volume, and per curved surface its measure
  // and radius (about the z axis if `axis`, else about the origin)
  struct Shape
  {
    double                                           volume;
    std::map<std::string, std::pair<double, double>> curved;
    bool                                             axis;
  };

  struct Measures
  {
    double                        volume = 0;
    std::map<std::string, double> surfaces;
    double                        node_off_surface = 0;
  };

  template <int dim>
  double
  radius(const Point<dim> &p, const bool axis)
  {
    return axis ? std::hypot(p[0], p[1]) : p.norm();
  }

  template <int dim>
  Measures
  measure(const Triangulation<dim>           &tria,
          const Mapping<dim>                 &mapping,
          const ContactDynamics::SceneLayout &layout,
          const Shape                        &shape)
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
    const FE_Q<dim>                           q2(2);
    FEFaceValues<dim>                         node_values(mapping,
                                  q2,
                                  Quadrature<dim - 1>(
                                    FE_Q<dim - 1>(2).get_unit_support_points()),
                                  update_quadrature_points);
    std::map<types::boundary_id, std::string> name_of;
    for (const auto &[name, id] : layout.surfaces)
      name_of[id] = name;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fe_values.reinit(cell);
        for (unsigned int k = 0; k < q.size(); ++k)
          m.volume += fe_values.JxW(k);
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const std::string &name = name_of[cell->face(f)->boundary_id()];
              face_values.reinit(cell, f);
              for (unsigned int k = 0; k < face_values.n_quadrature_points; ++k)
                m.surfaces[name] += face_values.JxW(k);
              const auto curved = shape.curved.find(name);
              if (cell->level() > 0 || curved == shape.curved.end())
                continue;
              node_values.reinit(cell, f);
              for (const auto &p : node_values.get_quadrature_points())
                m.node_off_surface = std::max(m.node_off_surface,
                                              std::abs(radius(p, shape.axis) -
                                                       curved->second.second));
            }
      }
    return m;
  }

  // the largest distance between the quadrature points of two mappings
  template <int dim>
  double
  mapping_difference(const Triangulation<dim> &tria,
                     const Mapping<dim>       &a,
                     const Mapping<dim>       &b)
  {
    const FE_Q<dim>   fe(1);
    const QGauss<dim> q(3);
    FEValues<dim>     va(a, fe, q, update_quadrature_points);
    FEValues<dim>     vb(b, fe, q, update_quadrature_points);
    double            worst = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        va.reinit(cell);
        vb.reinit(cell);
        for (unsigned int k = 0; k < q.size(); ++k)
          worst =
            std::max(worst,
                     va.quadrature_point(k).distance(vb.quadrature_point(k)));
      }
    return worst;
  }

  // Checks one file against `shape` within `tolerance` (relative); returns
  // the volume of the curved cells.
  template <int dim>
  double
  check_file(const std::string &file,
             const Shape       &shape,
             const double       tolerance,
             const double       reference_volume = 0)
  {
    const std::string name = file + ": ";
    const auto scene  = make_scene<dim>("gmsh", 1, [&](ParameterHandler &prm) {
      prm.set("Mesh file",
              file.find('/') == std::string::npos ? meshes + file : file);
    });
    const auto layout = scene.layout();
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

    const Measures m      = measure(tria, curved, layout, shape);
    const Measures chords = measure(tria, straight, layout, shape);
    const double   error  = std::abs(m.volume / shape.volume - 1);
    check_range(name + "|volume / exact - 1|", error, 0, tolerance);
    for (const auto &[surface, exact] : shape.curved)
      check_range(name + "|" + surface + " / exact - 1|",
                  std::abs(m.surfaces.at(surface) / exact.first - 1),
                  0,
                  tolerance);
    check_range(name + "straight cells' volume error / curved cells'",
                std::abs(chords.volume / shape.volume - 1) / error,
                100,
                1e12);
    check_range(name + "nodes of the curved surfaces off them",
                m.node_off_surface,
                0,
                1e-8);
    if (reference_volume > 0)
      check_close(name + "volume / the first format's - 1",
                  m.volume / reference_volume - 1,
                  0,
                  1e-14);

    tria.refine_global(dim == 2 ? 2 : 1);
    const Measures refined = measure(tria, curved, layout, shape);
    check_close(name + "refined: volume / coarse volume - 1",
                refined.volume / m.volume - 1,
                0,
                1e-12);
    return m.volume;
  }

  // the unit cube in unstructured hexahedra: straight cells, so the curved
  // mapping is the trilinear one
  void
  check_cube()
  {
    const std::string name = "cube_unstructured_order2.msh: ";
    const auto scene = make_scene<3>("gmsh", 1, [&](ParameterHandler &prm) {
      prm.set("Mesh file", meshes + "cube_unstructured_order2.msh");
    });
    Triangulation<3> tria;
    scene.create_triangulation(tria);
    ContactDynamics::GeometryMapping<3> curved;
    curved.set_geometry(scene.cell_geometry());
    const MappingQ<3> straight(1);
    deallog << name << tria.n_active_cells() << " cells" << std::endl;
    check_close(name + "curved mapping - MappingQ1 at the quadrature points",
                mapping_difference(tria, curved, straight),
                0,
                1e-12);
    const Measures m =
      measure(tria, curved, scene.layout(), Shape{1, {}, false});
    check_close(name + "volume - 1", m.volume - 1, 0, 1e-12);
  }
} // namespace

int
main()
{
  initlog();
  const double pi = numbers::PI;
  const Shape  annulus{3 * pi / 4,
                      {{"outer", {pi, 2.}}, {"inner", {pi / 2, 1.}}},
                      true};
  const double coarse =
    check_file<2>("quarter_annulus_order2.msh", annulus, 3e-4);
  check_file<2>("quarter_annulus_order2_v41.msh", annulus, 3e-4, coarse);
  check_file<2>("quarter_annulus_order2_parametric.msh", annulus, 3e-4, coarse);
  {
    // the 2.2 file with Windows line ends
    std::ifstream in(meshes + "quarter_annulus_order2.msh");
    std::ofstream out("annulus_crlf.msh");
    for (std::string line; std::getline(in, line);)
      out << line << "\r\n";
  }
  check_file<2>("./annulus_crlf.msh", annulus, 3e-4, coarse);
  const double fine =
    check_file<2>("quarter_annulus_order2_fine.msh", annulus, 3e-4);
  check_range("annulus: observed order of the area error, h to h/2",
              std::log2(std::abs(coarse / annulus.volume - 1) /
                        std::abs(fine / annulus.volume - 1)),
              3.5,
              6);

  const Shape  shell = annulus;
  const double shell_volume =
    check_file<3>("cylindrical_shell_order2.msh", shell, 3e-4);
  check_file<3>("cylindrical_shell_order2_v41.msh", shell, 3e-4, shell_volume);

  check_file<2>("disc_clockwise_order2.msh",
                Shape{pi, {{"rim", {2 * pi, 1.}}}, false},
                1e-4);
  check_file<3>("ball_order2.msh",
                Shape{4 * pi / 3, {{"surface", {4 * pi, 1.}}}, false},
                1e-3);
  check_cube();
}
