// The geometry of a simulation: all bodies in one triangulation, a material
// id per body and a boundary id per named surface. Each scene is a class in
// source/scenes/ listed in the registry (scene_registry.h); Scene<dim> is
// the one the parameter file selects.
#ifndef contact_dynamics_scenes_scene_h
#define contact_dynamics_scenes_scene_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/scene_layout.h>

#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  template <int dim>
  class QuadraticGeometry;

  /**
   * What every scene provides. The bodies of a scene never share vertices,
   * even where they touch, so that they can separate.
   */
  template <int dim>
  class SceneBase
  {
  public:
    virtual ~SceneBase() = default;

    /** Reads the scene's own entries; `prm` is in subsection Scene. */
    virtual void
    parse_parameters(ParameterHandler &prm) = 0;

    /** Bodies and surfaces, known without building the mesh. */
    virtual SceneLayout
    layout() const = 0;

    /** Builds the mesh into an empty triangulation. */
    virtual void
    create_triangulation(Triangulation<dim> &triangulation) const = 0;

    /**
     * The curved geometry of the coarse cells of the last triangulation
     * created, where the scene's mesh gives it by nodes (a Gmsh file of
     * second order); null where the manifolds give it.
     */
    virtual std::shared_ptr<const QuadraticGeometry<dim>>
    cell_geometry() const
    {
      return nullptr;
    }
  };

  /** The scene a parameter file selects (subsection Scene). */
  template <int dim>
  class Scene
  {
  public:
    /** Declares the selection and the entries of every registered scene. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Selects the scene (it must exist in dim) and reads its entries. */
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

    /** See SceneBase::cell_geometry(). */
    std::shared_ptr<const QuadraticGeometry<dim>>
    cell_geometry() const;

  private:
    std::string                     scene_name;
    std::shared_ptr<SceneBase<dim>> scene;
  };
} // namespace ContactDynamics

#endif
