#include <contact_dynamics/scenes/scene_registry.h>

// Every scene, one line each, in the order of the documentation. A scene
// `x` is a file source/scenes/x.cc that defines `SceneEntry x_scene()`.
#define CONTACT_DYNAMICS_SCENES(SCENE) \
  SCENE(bouncing_block)                \
  SCENE(ironing)                       \
  SCENE(patch_test)                    \
  SCENE(hertz)                         \
  SCENE(bar_impact)                    \
  SCENE(block)                         \
  SCENE(two_blocks)                    \
  SCENE(gmsh)

namespace ContactDynamics
{
#define CONTACT_DYNAMICS_DECLARE_SCENE(x) SceneEntry x##_scene();
  CONTACT_DYNAMICS_SCENES(CONTACT_DYNAMICS_DECLARE_SCENE)
#undef CONTACT_DYNAMICS_DECLARE_SCENE

  const std::vector<SceneEntry> &
  scene_registry()
  {
#define CONTACT_DYNAMICS_LIST_SCENE(x) x##_scene(),
    static const std::vector<SceneEntry> entries = {
      CONTACT_DYNAMICS_SCENES(CONTACT_DYNAMICS_LIST_SCENE)};
#undef CONTACT_DYNAMICS_LIST_SCENE
    return entries;
  }



  std::string
  scene_names(const int dim, const std::string &separator)
  {
    std::string names;
    for (const SceneEntry &entry : scene_registry())
      if (entry.exists_in(dim))
        names += (names.empty() ? "" : separator) + entry.name;
    return names;
  }
} // namespace ContactDynamics
