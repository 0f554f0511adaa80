// Gmsh scenes: what the parameters cannot tell before the mesh file is read.
// A 3-D mesh read with Dimension = 2 (and a 2-D one with Dimension = 3) must
// say so, naming the file, instead of listing no surfaces; a contact pair of
// two surfaces of one body must be refused, naming the pair and the body
// (the built-in scenes refuse it while reading the parameters, a Gmsh
// scene once the mesh is there, before the first step). A mesh of second
// order must name its fault before the first step: serendipity elements
// (8-node quadrilaterals), cells of first and second order mixed, a cell
// folded by its centre node (its Jacobian changes sign inside) or by a
// mid-side node (only on that side), a cell with two coincident corners,
// triangles of second order, an element line cut short.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/application.h>

#include "tests.h"

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace
{
  const char *cube = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
2 2 "faces"
3 1 "cube"
$EndPhysicalNames
$Nodes
8
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 0 0 1
6 1 0 1
7 1 1 1
8 0 1 1
$EndNodes
$Elements
7
1 3 2 2 1 1 4 3 2
2 3 2 2 1 5 6 7 8
3 3 2 2 1 1 2 6 5
4 3 2 2 1 2 3 7 6
5 3 2 2 1 3 4 8 7
6 3 2 2 1 4 1 5 8
7 5 2 1 1 1 2 3 4 5 6 7 8
$EndElements
)";

  // the names of the plate's body and sides
  const std::string plate_names = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
4
1 2 "bottom"
1 3 "top"
1 4 "sides"
2 1 "plate"
$EndPhysicalNames
)";

  const std::string plate = plate_names + R"($Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
5
1 1 2 2 1 1 2
2 1 2 4 2 2 3
3 1 2 3 3 3 4
4 1 2 4 4 4 1
5 3 2 1 1 1 2 3 4
$EndElements
)";

  // the plate in one 9-node quadrilateral with 3-node sides; `cell` is the
  // element line of the cell (lines: `cells` elements in all)
  std::string
  plate_of_second_order(const std::string &cell, const unsigned int cells = 5)
  {
    return plate_names + R"($Nodes
9
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 0.5 0 0
6 1 0.5 0
7 0.5 1 0
8 0 0.5 0
9 0.5 0.5 0
$EndNodes
$Elements
)" + std::to_string(cells) +
           R"(
1 8 2 2 1 1 2 5
2 8 2 4 2 2 3 6
3 8 2 3 3 3 4 7
4 8 2 4 4 4 1 8
)" + cell + "\n$EndElements\n";
  }

  // Runs (or validates) the parameter file `text` and writes its error.
  void
  expect_error(const std::string &label,
               const std::string &text,
               const bool         validate_only)
  {
    const std::string filename = "input.prm";
    std::ofstream(filename) << text;
    std::ostringstream screen;
    try
      {
        ContactDynamics::run_parameter_file(filename, screen, validate_only);
        dealii::deallog << label << ": no error (FAILED)" << std::endl;
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        dealii::deallog << label << ": " << info.str() << std::endl;
      }
  }
} // namespace

int
main()
{
  initlog();
  std::ofstream("cube.msh") << cube;
  std::ofstream("plate.msh") << plate;

  expect_error("3-D mesh, Dimension = 2",
               "set Dimension = 2\n"
               "subsection Scene\n"
               "  set Scene = gmsh\n"
               "  set Mesh file = cube.msh\n"
               "end\n",
               true);
  expect_error("2-D mesh, Dimension = 3",
               "set Dimension = 3\n"
               "subsection Scene\n"
               "  set Scene = gmsh\n"
               "  set Mesh file = plate.msh\n"
               "end\n",
               true);
  expect_error("pair on one body",
               "subsection Scene\n"
               "  set Scene = gmsh\n"
               "  set Mesh file = plate.msh\n"
               "end\n"
               "subsection Contact\n"
               "  set Formulation = mortar\n"
               "  set Pairs = bottom: top\n"
               "end\n"
               "subsection Time integration\n"
               "  set End time = 0.1\n"
               "end\n"
               "subsection Output\n"
               "  set Output directory = output_plate\n"
               "  set VTU interval = 0\n"
               "end\n",
               false);

  // second order: what the file's nodes cannot give
  const std::map<std::string, std::string> second_order = {
    {"serendipity", plate_of_second_order("5 16 2 1 1 1 2 3 4 5 6 7 8")},
    {"mixed orders",
     plate_of_second_order("5 10 2 1 1 1 2 3 4 5 6 7 8 9\n6 3 2 1 1 1 2 3 4",
                           6)},
    {"folded", plate_of_second_order("5 10 2 1 1 1 2 3 4 5 6 7 8 9")},
    {"folded at a side", plate_of_second_order("5 10 2 1 1 1 2 3 4 5 6 7 8 9")},
    {"coincident corners",
     plate_of_second_order("5 10 2 1 1 1 2 3 4 5 6 7 8 9")},
    {"triangles of second order",
     plate_of_second_order("5 9 2 1 1 1 2 3 5 6 9")},
    {"cut element", plate_of_second_order("5 10 2 1 1 1 2 3 4 5")}};
  for (const auto &[label, mesh] : second_order)
    {
      std::string text = mesh;
      if (label == "folded") // the centre node beyond the right side
        text.replace(text.find("9 0.5 0.5 0"), 11, "9 3 0.5 0");
      // the bottom's mid-side node pulled up by 0.35: det J < 0 only on
      // that side (the Gauss points inside stay positive)
      if (label == "coincident corners") // node 4 onto node 3
        text.replace(text.find("4 0 1 0"), 7, "4 1 1 0");
      if (label == "folded at a side")
        text.replace(text.find("5 0.5 0 0"), 9, "5 0.5 0.35 0");
      std::ofstream(label + ".msh") << text;
      expect_error(label,
                   "subsection Scene\n"
                   "  set Scene = gmsh\n"
                   "  set Mesh file = " +
                     label +
                     ".msh\n"
                     "end\n"
                     "subsection Finite element\n"
                     "  set Polynomial degree = 2\n"
                     "end\n"
                     "subsection Output\n"
                     "  set Output directory = output_plate\n"
                     "end\n",
                   false);
    }
}
