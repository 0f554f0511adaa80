// Gmsh files of second order (3-node lines, 9-node quadrilaterals, 27-node
// hexahedra), which deal.II's GridIn does not read: the file is rewritten
// with their corner elements for GridIn, and the other nodes give the
// curved geometry of the cells (QuadraticGeometry).
#ifndef contact_dynamics_scenes_gmsh_second_order_h
#define contact_dynamics_scenes_gmsh_second_order_h

#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/quadratic_geometry.h>

#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  namespace GmshReader
  {
    /** "The mesh file '<file>' (parameter Scene/Mesh file) ": errors start so.
     */
    std::string
    file_error(const std::string &file);

    template <int dim>
    struct SecondOrderFile
    {
      /** Whether the file has elements of second order. */
      bool second_order = false;
      /**
       * Whether the file had to be rewritten for GridIn (second order, or
       * the parametric coordinates of format 4.1), into corner_text: the
       * elements of second order as their corner elements.
       */
      bool        rewritten = false;
      std::string corner_text;
      /** The nodes of each cell of dimension dim, in Gmsh's order. */
      std::vector<std::vector<Point<dim>>> cell_nodes;
    };

    /**
     * Reads an ASCII file of format 2.2 or 4.1; anything else (another
     * version, binary) and a file of first order that it cannot parse come
     * back with rewritten = false and are left to GridIn. Throws a message
     * naming the file for serendipity elements (8-node quadrilaterals,
     * 20-node hexahedra), triangles and tetrahedra of second order, and
     * meshes that mix cells of second order with others.
     */
    template <int dim>
    SecondOrderFile<dim>
    read_second_order(const std::string &file);

    /**
     * The nodes of the coarse cells of `triangulation` (made from the corner
     * elements) in deal.II's order, each cell found by its corners.
     */
    template <int dim>
    std::shared_ptr<const QuadraticGeometry<dim>>
    cell_geometry(const SecondOrderFile<dim> &file_nodes,
                  const Triangulation<dim>   &triangulation,
                  const std::string          &file);
  } // namespace GmshReader
} // namespace ContactDynamics

#endif
