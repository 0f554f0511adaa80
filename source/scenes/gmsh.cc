// A scene read from a Gmsh file (entry Mesh file).
#include <contact_dynamics/scenes/gmsh_reader.h>
#include <contact_dynamics/scenes/scene_registry.h>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class Gmsh : public SceneBase<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Mesh file",
          "",
          Patterns::Anything(),
          "Gmsh .msh file (format 2.2 or 4, ASCII) for the scene 'gmsh'. "
          "Physical groups of the cells are the bodies (numbered in the order "
          "of their tags), physical groups of the boundary faces are the "
          "surfaces; all of them need a name in $PhysicalNames. Cells of "
          "first order (4-node quadrilaterals, 8-node hexahedra) or, in "
          "formats 2.2 and 4.1, of second order (9-node quadrilaterals, "
          "27-node hexahedra: Mesh.ElementOrder = 2 with "
          "Mesh.SecondOrderIncomplete = 0), whose mid-side and centre nodes "
          "curve the cells with Finite element/Polynomial degree = 2.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        mesh_file = prm.get("Mesh file");
        // a missing or unnamed mesh file is reported now, not at mesh time
        file_layout = GmshReader::read_layout(mesh_file, dim);
      }

      SceneLayout
      layout() const override
      {
        return file_layout;
      }

      void
      create_triangulation(Triangulation<dim> &triangulation) const override
      {
        geometry = GmshReader::read_mesh(mesh_file, file_layout, triangulation);
      }

      std::shared_ptr<const QuadraticGeometry<dim>>
      cell_geometry() const override
      {
        return geometry;
      }

    private:
      std::string mesh_file;
      SceneLayout file_layout;
      // of the last mesh read (null for a mesh of first order)
      mutable std::shared_ptr<const QuadraticGeometry<dim>> geometry;
    };
  } // namespace

  SceneEntry
  gmsh_scene()
  {
    return scene_in_any_dimension<Gmsh>("gmsh", "read from Mesh file");
  }
} // namespace ContactDynamics
