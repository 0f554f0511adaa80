// The geometry of a simulation: all bodies in one triangulation, a material
// id per body and a boundary id per named surface.
#ifndef contact_dynamics_scenes_scene_h
#define contact_dynamics_scenes_scene_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * Names of the bodies and surfaces of a scene. Body i has material id i.
   * Every boundary face of the triangulation carries the boundary id of one
   * named surface.
   */
  struct SceneLayout
  {
    std::vector<std::string>                  body_names;
    std::map<std::string, types::boundary_id> surfaces;

    /** Material id of a body; throws a message listing the known bodies. */
    types::material_id
    body_id(const std::string &name) const;

    /** Boundary id of a surface; throws a message listing the known ones. */
    types::boundary_id
    surface_id(const std::string &name) const;
  };

  /**
   * Built-in parametric scenes (bouncing block, ironing, patch test, hertz,
   * bar impact, block) and scenes read from Gmsh files whose physical groups
   * name the bodies (cells) and surfaces (boundary faces).
   *
   * The bodies of a scene never share vertices, even where they touch, so
   * that they can separate.
   */
  template <int dim>
  class Scene
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** The scene name as written in the parameter file. */
    const std::string &
    name() const;

    /**
     * Bodies and surfaces, known without building the mesh (for a Gmsh scene
     * the file's physical names are read).
     */
    SceneLayout
    layout() const;

    /** Builds the mesh; the triangulation must be empty. */
    void
    create_triangulation(Triangulation<dim> &triangulation) const;

  private:
    std::string scene_name;
    double      refinement_factor;
    std::string mesh_file;

    // "block" scene
    std::vector<double>       block_origin;
    std::vector<double>       block_size;
    std::vector<unsigned int> block_subdivisions;

    // "hertz" scene
    double hertz_radius;
    double hertz_block_width;
    double hertz_block_height;
    double hertz_gap;

    // "bar impact" scene
    double       bar_length;
    double       bar_height;
    double       bar_gap;
    std::string  bar_target;
    double       bar_target_length;
    unsigned int bar_elements;
  };
} // namespace ContactDynamics

#endif
