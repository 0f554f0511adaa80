// Names of the bodies and surfaces of a scene, without the mesh: what the
// parameter reader, the boundary conditions and the contact pairs need.
#ifndef contact_dynamics_scenes_scene_layout_h
#define contact_dynamics_scenes_scene_layout_h

#include <deal.II/base/types.h>

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
    // The body (material id) of each surface where the scene knows it
    // without the mesh (the built-in scenes); empty for a Gmsh scene.
    std::map<std::string, types::material_id> surface_body;
    // The rigid obstacles of 'Contact/Rigid obstacles' (no mesh).
    std::vector<std::string> obstacle_names;

    /** Material id of a body; throws a message listing the known bodies. */
    types::material_id
    body_id(const std::string &name) const;

    /** Boundary id of a surface; throws a message listing the known ones. */
    types::boundary_id
    surface_id(const std::string &name) const;
  };
} // namespace ContactDynamics

#endif
