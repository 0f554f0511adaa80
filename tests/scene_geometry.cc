// Geometry of the scenes: body areas, surface lengths against hand-computed
// values, bodies that share no vertex, named boundary faces, cell quality of
// the ironing tool, refinement factor, a Gmsh round trip and the error
// messages.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/scene.h>

#include "tests.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

using namespace dealii;
using namespace ContactDynamics;

template <int dim>
double
body_measure(const Triangulation<dim> &tria, const unsigned int body)
{
  double measure = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->material_id() == body)
      measure += cell->measure();
  return measure;
}

template <int dim>
unsigned int
n_body_cells(const Triangulation<dim> &tria, const unsigned int body)
{
  unsigned int n = 0;
  for (const auto &cell : tria.active_cell_iterators())
    n += (cell->material_id() == body);
  return n;
}

template <int dim>
std::pair<double, unsigned int>
surface_measure(const Triangulation<dim> &tria, const types::boundary_id id)
{
  double       measure = 0;
  unsigned int n       = 0;
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        {
          measure += face->measure();
          ++n;
        }
  return {measure, n};
}

std::string
message_of(const ExceptionBase &e)
{
  std::ostringstream out;
  e.print_info(out);
  return Utilities::trim(out.str());
}

// Checks that hold for every scene, and the areas/lengths against the
// expected values (relative tolerance).
template <int dim>
void
check_scene(const std::string                   &label,
            const Triangulation<dim>            &tria,
            const SceneLayout                   &layout,
            const std::vector<std::string>      &bodies,
            const std::vector<double>           &measures,
            const std::map<std::string, double> &surfaces,
            const double                         tolerance)
{
  deallog << label << ": " << tria.n_active_cells() << " cells";
  for (unsigned int b = 0; b < layout.body_names.size(); ++b)
    deallog << ", " << layout.body_names[b] << " " << n_body_cells(tria, b);
  deallog << std::endl;

  check_true(label + ": body names", layout.body_names == bodies);
  for (unsigned int b = 0; b < bodies.size(); ++b)
    check_close(label + ": measure of " + bodies[b],
                body_measure(tria, layout.body_id(bodies[b])),
                measures[b],
                tolerance * measures[b]);

  std::set<std::string> names;
  for (const auto &[name, id] : layout.surfaces)
    names.insert(name);
  std::set<std::string> expected_names;
  for (const auto &[name, length] : surfaces)
    expected_names.insert(name);
  check_true(label + ": surface names", names == expected_names);
  for (const auto &[name, length] : surfaces)
    check_close(label + ": measure of " + name,
                surface_measure(tria, layout.surface_id(name)).first,
                length,
                tolerance * length);

  // Bodies share no vertex.
  std::vector<int> body_of_vertex(tria.n_vertices(), -1);
  bool             separate = true;
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      {
        int &b = body_of_vertex[cell->vertex_index(v)];
        if (b != -1 && b != static_cast<int>(cell->material_id()))
          separate = false;
        b = cell->material_id();
      }
  check_true(label + ": no vertex shared between bodies", separate);

  std::set<types::boundary_id> ids;
  for (const auto &[name, id] : layout.surfaces)
    ids.insert(id);
  bool all_named = true, all_positive = true, known_bodies = true;
  for (const auto &cell : tria.active_cell_iterators())
    {
      all_positive &= (cell->measure() > 0);
      known_bodies &= (cell->material_id() < layout.body_names.size());
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          all_named &= (ids.count(face->boundary_id()) == 1);
    }
  check_true(label + ": every cell in a named body", known_bodies);
  check_true(label + ": every boundary face on a named surface", all_named);
  check_true(label + ": all cells have positive measure", all_positive);
}

// Interior angles (degrees) of the quadrilaterals of one body.
std::pair<double, double>
angle_range(const Triangulation<2> &tria, const unsigned int body)
{
  double min_angle = 360, max_angle = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->material_id() == body)
      {
        // Vertices in the order around the cell.
        const unsigned int order[4] = {0, 1, 3, 2};
        for (unsigned int k = 0; k < 4; ++k)
          {
            const Point<2>     p    = cell->vertex(order[k]);
            const Tensor<1, 2> a    = cell->vertex(order[(k + 3) % 4]) - p;
            const Tensor<1, 2> b    = cell->vertex(order[(k + 1) % 4]) - p;
            const double       cosv = a * b / (a.norm() * b.norm());
            const double       angle =
              std::acos(std::max(-1.0, std::min(1.0, cosv))) * 180 /
              numbers::PI;
            min_angle = std::min(min_angle, angle);
            max_angle = std::max(max_angle, angle);
          }
      }
  return {min_angle, max_angle};
}

const char *gmsh_file = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
7
1 1 "lower_bottom"
1 2 "lower_top"
1 3 "lower_sides"
1 7 "upper_bottom"
1 8 "upper_rest"
2 5 "upper"
2 10 "lower"
$EndPhysicalNames
$Nodes
10
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
7 0.5 1 0
8 1.5 1 0
9 1.5 2 0
10 0.5 2 0
$EndNodes
$Elements
13
1 3 2 10 1 1 2 5 4
2 3 2 10 1 2 3 6 5
3 3 2 5 2 7 8 9 10
4 1 2 1 3 1 2
5 1 2 1 3 2 3
6 1 2 2 4 5 4
7 1 2 2 4 6 5
8 1 2 3 5 1 4
9 1 2 3 5 3 6
10 1 2 7 6 7 8
11 1 2 8 7 8 9
12 1 2 8 7 9 10
13 1 2 8 7 10 7
$EndElements
)";

int
main()
{
  initlog();
  const double pi = numbers::PI;

  // Bouncing block.
  {
    const Scene<2>   scene = make_scene<2>("bouncing block");
    Triangulation<2> tria;
    scene.create_triangulation(tria);
    check_scene<2>("bouncing block",
                   tria,
                   scene.layout(),
                   {"block", "substrate"},
                   {1, 5},
                   {{"block_bottom", 1},
                    {"block_top", 1},
                    {"block_left", 1},
                    {"block_right", 1},
                    {"substrate_top", 5},
                    {"substrate_bottom", 5},
                    {"substrate_left", 1},
                    {"substrate_right", 1}},
                   1e-12);
  }

  // Ironing: the tool is a 2 x 1 rectangle on a half-disc of radius 1.
  {
    const Scene<2>    scene  = make_scene<2>("ironing");
    const SceneLayout layout = scene.layout();
    Triangulation<2>  tria;
    scene.create_triangulation(tria);
    check_scene<2>("ironing",
                   tria,
                   layout,
                   {"tool", "substrate"},
                   {2 + pi / 2, 48},
                   {{"tool_arc", pi},
                    {"tool_sides", 2},
                    {"tool_top", 2},
                    {"substrate_top", 12},
                    {"substrate_bottom", 12},
                    {"substrate_left", 4},
                    {"substrate_right", 4}},
                   1e-3);
    // The straight parts exactly.
    check_close("ironing: tool_sides exact",
                surface_measure(tria, layout.surface_id("tool_sides")).first,
                2,
                1e-12);
    check_close("ironing: tool_top exact",
                surface_measure(tria, layout.surface_id("tool_top")).first,
                2,
                1e-12);
    check_close("ironing: substrate exact", body_measure(tria, 1), 48, 1e-12);

    const auto arc = surface_measure(tria, layout.surface_id("tool_arc"));
    const auto top = surface_measure(tria, layout.surface_id("substrate_top"));
    deallog << "ironing: tool_arc faces " << arc.second
            << ", substrate_top faces " << top.second << std::endl;
    check_true("ironing: arc at least as fine as the substrate top",
               arc.first / arc.second <= top.first / top.second);

    const auto [min_angle, max_angle] =
      angle_range(tria, layout.body_id("tool"));
    std::cout << "ironing tool angles: " << min_angle << " .. " << max_angle
              << std::endl;
    check_true("ironing: tool cell angles in [30, 150] degrees",
               min_angle >= 30 && max_angle <= 150);

    // Arc vertices lie on the circle, also after refinement (manifold).
    tria.refine_global(1);
    double max_error = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            face->boundary_id() == layout.surface_id("tool_arc"))
          for (const unsigned int v : face->vertex_indices())
            max_error =
              std::max(max_error,
                       std::abs(face->vertex(v).distance(Point<2>(1.2, 5.02)) -
                                1));
    check_close("ironing: refined arc vertices on the circle",
                max_error,
                0,
                1e-12);

    // Refinement factor 2 doubles the element counts.
    const Scene<2>   fine_scene = make_scene<2>("ironing", 2);
    Triangulation<2> fine;
    fine_scene.create_triangulation(fine);
    check_true("ironing factor 2: substrate_top faces doubled",
               surface_measure(fine, layout.surface_id("substrate_top"))
                   .second == 2 * top.second);
    check_true("ironing factor 2: tool_arc faces doubled",
               surface_measure(fine, layout.surface_id("tool_arc")).second ==
                 2 * arc.second);
    check_close("ironing factor 2: tool area",
                body_measure(fine, 0),
                2 + pi / 2,
                1e-3 / 4 * (2 + pi / 2));
  }

  // Patch test: non-matching meshes at y = 0.5.
  {
    const Scene<2>   scene = make_scene<2>("patch test");
    Triangulation<2> tria;
    scene.create_triangulation(tria);
    check_scene<2>("patch test",
                   tria,
                   scene.layout(),
                   {"upper", "lower"},
                   {0.5, 0.5},
                   {{"upper_top", 1},
                    {"upper_bottom", 1},
                    {"upper_left", 0.5},
                    {"upper_right", 0.5},
                    {"lower_top", 1},
                    {"lower_bottom", 1},
                    {"lower_left", 0.5},
                    {"lower_right", 0.5}},
                   1e-12);
  }

  // Hertz with the default radius 1 and block 8 x 4.
  {
    const Scene<2>    scene  = make_scene<2>("hertz");
    const SceneLayout layout = scene.layout();
    Triangulation<2>  tria;
    scene.create_triangulation(tria);
    check_scene<2>("hertz",
                   tria,
                   layout,
                   {"cylinder", "block"},
                   {pi / 2, 32},
                   {{"cylinder_arc", pi},
                    {"cylinder_top", 2},
                    {"block_top", 8},
                    {"block_bottom", 8},
                    {"block_left", 4},
                    {"block_right", 4}},
                   1e-3);
    check_close("hertz: block area exact", body_measure(tria, 1), 32, 1e-10);
    check_close("hertz: cylinder_top exact",
                surface_measure(tria, layout.surface_id("cylinder_top")).first,
                2,
                1e-12);
    // The lowest point of the cylinder touches the block top (gap 0).
    double lowest = 1e9;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() == 0)
        for (const unsigned int v : cell->vertex_indices())
          lowest = std::min(lowest, cell->vertex(v)[1]);
    check_close("hertz: lowest cylinder point at the block top",
                lowest,
                4,
                1e-12);
    const auto arc = surface_measure(tria, layout.surface_id("cylinder_arc"));
    check_true("hertz: arc elements at most R/40",
               arc.first / arc.second <= 1.0 / 40);
  }

  // Bar impact, wall and bar targets.
  {
    const Scene<2>   scene = make_scene<2>("bar impact");
    Triangulation<2> tria;
    scene.create_triangulation(tria);
    check_scene<2>("bar impact (wall)",
                   tria,
                   scene.layout(),
                   {"striker", "target"},
                   {0.1, 0.02},
                   {{"striker_left", 0.1},
                    {"striker_right", 0.1},
                    {"striker_top", 1},
                    {"striker_bottom", 1},
                    {"target_left", 0.1},
                    {"target_right", 0.1},
                    {"target_top", 0.2},
                    {"target_bottom", 0.2}},
                   1e-12);

    const Scene<2> bar_scene =
      make_scene<2>("bar impact", 1, [](ParameterHandler &prm) {
        prm.enter_subsection("Bar impact");
        prm.set("Target", "bar");
        prm.set("Target length", "0.5");
        prm.leave_subsection();
      });
    Triangulation<2> bar;
    bar_scene.create_triangulation(bar);
    check_scene<2>("bar impact (bar)",
                   bar,
                   bar_scene.layout(),
                   {"striker", "target"},
                   {0.1, 0.05},
                   {{"striker_left", 0.1},
                    {"striker_right", 0.1},
                    {"striker_top", 1},
                    {"striker_bottom", 1},
                    {"target_left", 0.1},
                    {"target_right", 0.1},
                    {"target_top", 0.5},
                    {"target_bottom", 0.5}},
                   1e-12);
  }

  // Block in 2-D (defaults) and 3-D.
  {
    const Scene<2>   scene = make_scene<2>("block");
    Triangulation<2> tria;
    scene.create_triangulation(tria);
    check_scene<2>("block 2d",
                   tria,
                   scene.layout(),
                   {"body"},
                   {1},
                   {{"left", 1}, {"right", 1}, {"bottom", 1}, {"top", 1}},
                   1e-12);

    const Scene<3> scene3 =
      make_scene<3>("block", 1, [](ParameterHandler &prm) {
        prm.enter_subsection("Block");
        prm.set("Origin", "0, 0, 0");
        prm.set("Size", "1, 2, 3");
        prm.set("Subdivisions", "1, 2, 3");
        prm.leave_subsection();
      });
    Triangulation<3> tria3;
    scene3.create_triangulation(tria3);
    // the 3-D ironing and Hertz: spherical caps (every vertex of the cap
    // on the sphere), flat tops, boxes below
    const auto check_cap = [](const std::string  &label,
                              const Scene<3>     &scene,
                              const std::string  &cap,
                              const Point<3>     &centre,
                              const double        top_area,
                              const std::string  &box,
                              const double        box_volume,
                              const double        box_top_area) {
      Triangulation<3> tria;
      scene.create_triangulation(tria);
      const auto &layout = scene.layout();
      deallog << label << ": " << tria.n_active_cells() << " cells"
              << std::endl;
      double       off_sphere = 0;
      unsigned int n_faces    = 0;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() &&
            face->boundary_id() == layout.surface_id(cap + "_bottom"))
          {
            ++n_faces;
            for (const unsigned int v : face->vertex_indices())
              off_sphere = std::max(off_sphere,
                                    std::abs(face->vertex(v).distance(centre) - 1));
          }
      check_true(label + ": cap faces", n_faces > 10);
      check_close(label + ": cap vertices on the sphere", off_sphere, 0, 1e-12);
      check_close(label + ": measure of " + cap + "_top",
                  surface_measure(tria, layout.surface_id(cap + "_top")).first,
                  top_area,
                  1e-12);
      check_close(label + ": measure of " + box,
                  body_measure(tria, layout.body_id(box)),
                  box_volume,
                  1e-12 * box_volume);
      check_close(label + ": measure of " + box + "_top",
                  surface_measure(tria, layout.surface_id(box + "_top")).first,
                  box_top_area,
                  1e-12 * box_top_area);
      std::size_t unnamed = 0;
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() &&
            face->boundary_id() == numbers::internal_face_boundary_id)
          ++unnamed;
      check_true(label + ": every boundary face named", unnamed == 0);
    };
    check_cap("ironing 3d",
              make_scene<3>("ironing"),
              "tool",
              Point<3>(1.2, 2.52, 0),
              1.2 * 0.6,
              "substrate",
              6 * 1.5 * 1.5,
              6 * 1.5);
    check_cap("hertz 3d",
              make_scene<3>("hertz"),
              "sphere",
              Point<3>(0, 5, 0),
              0.4 * 0.4,
              "block",
              4 * 4 * 4,
              4 * 4);

    check_scene<3>("block 3d",
                   tria3,
                   scene3.layout(),
                   {"body"},
                   {6},
                   {{"left", 6},
                    {"right", 6},
                    {"bottom", 3},
                    {"top", 3},
                    {"front", 2},
                    {"back", 2}},
                   1e-12);
  }

  // Gmsh round trip: bodies numbered by tag (5 "upper", 10 "lower").
  {
    std::ofstream("scene_geometry.msh") << gmsh_file;
    const Scene<2> scene = make_scene<2>("gmsh", 1, [](ParameterHandler &prm) {
      prm.set("Mesh file", "scene_geometry.msh");
    });
    Triangulation<2> tria;
    scene.create_triangulation(tria);
    check_scene<2>("gmsh",
                   tria,
                   scene.layout(),
                   {"upper", "lower"},
                   {1, 2},
                   {{"lower_bottom", 2},
                    {"lower_top", 2},
                    {"lower_sides", 2},
                    {"upper_bottom", 1},
                    {"upper_rest", 3}},
                   1e-12);
  }

  // Error messages.
  const auto print_error = [](const std::string           &label,
                              const std::function<void()> &f) {
    try
      {
        f();
        deallog << label << ": no exception" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        deallog << label << ": " << message_of(e) << std::endl;
      }
  };
  print_error("unknown surface", [] {
    make_scene<2>("bouncing block").layout().surface_id("blok_top");
  });
  print_error("unknown body", [] {
    make_scene<2>("patch test").layout().body_id("top");
  });
  print_error("bar impact in 3-D", [] {
    Triangulation<3> tria;
    make_scene<3>("bar impact").create_triangulation(tria);
  });
  print_error("block size entries", [] {
    make_scene<2>("block", 1, [](ParameterHandler &prm) {
      prm.enter_subsection("Block");
      prm.set("Size", "1, 1, 1");
      prm.leave_subsection();
    });
  });
  print_error("missing mesh file", [] {
    make_scene<2>("gmsh", 1, [](ParameterHandler &prm) {
      prm.set("Mesh file", "no_such_file.msh");
    });
  });
}
