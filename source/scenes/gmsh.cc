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
          "surfaces; all of them need a name in $PhysicalNames.");
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
        GmshReader::read_mesh(mesh_file, file_layout, triangulation);
      }

    private:
      std::string mesh_file;
      SceneLayout file_layout;
    };
  } // namespace

  SceneEntry
  gmsh_scene()
  {
    return scene_in_any_dimension<Gmsh>("gmsh", "read from Mesh file");
  }
} // namespace ContactDynamics
