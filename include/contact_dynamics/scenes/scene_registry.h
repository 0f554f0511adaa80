// The list of scenes: the selection pattern of Scene/Scene, its
// documentation and the check of the space dimension all come from it.
#ifndef contact_dynamics_scenes_scene_registry_h
#define contact_dynamics_scenes_scene_registry_h

#include <contact_dynamics/scenes/scene.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  /** A scene as the registry knows it. */
  struct SceneEntry
  {
    std::string name;        // as in the parameter file
    std::string description; // a phrase for the documentation
    std::function<void(ParameterHandler &)>        declare_parameters;
    std::function<std::unique_ptr<SceneBase<2>>()> create_2d;
    std::function<std::unique_ptr<SceneBase<3>>()> create_3d; // empty: 2-D only

    bool
    exists_in(const int dim) const
    {
      return dim == 2 ? bool(create_2d) : bool(create_3d);
    }

    template <int dim>
    std::unique_ptr<SceneBase<dim>>
    create() const
    {
      if constexpr (dim == 2)
        return create_2d();
      else
        return create_3d();
    }
  };

  /** A 2-D scene: a class derived from SceneBase<2>. */
  template <class SceneClass>
  SceneEntry
  planar_scene(const std::string &name, const std::string &description)
  {
    return {name,
            description,
            &SceneClass::declare_parameters,
            [] {
              return std::make_unique<SceneClass>();
            },
            {}};
  }

  /** A scene in 2-D and 3-D: a class template derived from SceneBase<dim>. */
  template <template <int> class SceneClass>
  SceneEntry
  scene_in_any_dimension(const std::string &name,
                         const std::string &description)
  {
    return {name,
            description,
            &SceneClass<2>::declare_parameters,
            [] {
              return std::make_unique<SceneClass<2>>();
            },
            [] {
              return std::make_unique<SceneClass<3>>();
            }};
  }

  /** Every scene, in the order of the documentation. */
  const std::vector<SceneEntry> &
  scene_registry();

  /** Names of the scenes that exist in dim, joined by `separator`. */
  std::string
  scene_names(const int dim, const std::string &separator);
} // namespace ContactDynamics

#endif
