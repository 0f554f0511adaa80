// Scenes read from Gmsh files: physical groups of the cells are the bodies,
// physical groups of the boundary faces the surfaces, all named in
// $PhysicalNames.
#ifndef contact_dynamics_scenes_gmsh_reader_h
#define contact_dynamics_scenes_gmsh_reader_h

#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/scene.h>

#include <memory>
#include <string>

namespace ContactDynamics
{
  template <int dim>
  class QuadraticGeometry;

  namespace GmshReader
  {
    /**
     * Bodies and surfaces named in the file's $PhysicalNames (ordered by
     * tag); throws a message naming the parameter Scene/Mesh file if the
     * file is missing, unreadable or names no body of dimension dim.
     */
    SceneLayout
    read_layout(const std::string &file, const int dim);

    /**
     * Reads the mesh into an empty triangulation: material ids from the
     * layout's bodies, boundary ids from its surfaces; bodies meshed with
     * common nodes get separate vertices. Returns the cells' curved geometry
     * if the file's cells are of second order (9-node quadrilaterals,
     * 27-node hexahedra), else null.
     */
    template <int dim>
    std::shared_ptr<const QuadraticGeometry<dim>>
    read_mesh(const std::string  &file,
              const SceneLayout  &layout,
              Triangulation<dim> &triangulation);
  } // namespace GmshReader
} // namespace ContactDynamics

#endif
