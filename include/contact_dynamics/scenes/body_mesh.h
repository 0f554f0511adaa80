// Meshing helpers of the built-in scenes: bodies meshed one by one (their
// own vertices, cells and named surfaces) and put into one triangulation
// without shared vertices, graded step sequences, and the two body shapes
// of the built-in scenes (rectangles and half-discs).
#ifndef contact_dynamics_scenes_body_mesh_h
#define contact_dynamics_scenes_body_mesh_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <contact_dynamics/scenes/scene.h>

#include <functional>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * One body's own vertices and cells, and which of its surfaces a boundary
   * face belongs to (decided by the face centre).
   */
  template <int dim>
  struct BodyMesh
  {
    std::vector<Point<dim>>                        vertices;
    std::vector<CellData<dim>>                     cells;
    std::function<std::string(const Point<dim> &)> surface_of;

    // A surface on a circle (cylinder) that gets a SphericalManifold.
    std::string curved_surface;
    Point<dim>  curve_center;
  };

  /**
   * A body of a built-in scene: its name, the names of its surfaces (the
   * values BodyMesh::surface_of returns) and how to mesh it. The scene's
   * layout and its mesh both come from these, so they cannot disagree.
   */
  template <int dim>
  struct BodyDefinition
  {
    std::string                    name;
    std::vector<std::string>       surfaces;
    std::function<BodyMesh<dim>()> mesh;
  };

  /** Body i -> material id i, the surfaces numbered in the order given. */
  template <int dim>
  SceneLayout
  layout_of(const std::vector<BodyDefinition<dim>> &bodies);

  /**
   * Meshes the bodies and puts them into one (empty) triangulation: body i
   * gets material id i, every boundary face the id of its surface in
   * layout_of(bodies), curved surfaces a SphericalManifold.
   */
  template <int dim>
  void
  mesh_bodies(const std::vector<BodyDefinition<dim>> &bodies,
              Triangulation<dim>                     &triangulation);

  namespace MeshSteps
  {
    /** max(1, round(count * factor)): an element count at a refinement. */
    unsigned int
    scaled(const double count, const double factor);

    std::vector<double>
    uniform(const double length, const unsigned int n);

    /**
     * n steps first*r^i (i = 0..n-1) that add up to length, r >= 1; uniform
     * steps if the first step is already too long for a growing sequence.
     */
    std::vector<double>
    geometric(const double length, const double first, const unsigned int n);

    /**
     * Number of geometrically growing steps (ratio r) that start at size h
     * and cover the given length.
     */
    unsigned int
    n_growing(const double length, const double h, const double r);

    std::vector<double>
    reversed(std::vector<double> v);

    std::vector<double>
    concatenate(std::vector<double> a, const std::vector<double> &b);
  } // namespace MeshSteps

  /**
   * Surface names of an axis-parallel box: prefix + left, right, bottom,
   * top (and front, back in 3-D).
   */
  std::vector<std::string>
  box_surface_names(const std::string &prefix, const unsigned int dim);

  /** The surface of a box [p0, p1] a face centre lies on ("" if none). */
  template <int dim>
  std::function<std::string(const Point<dim> &)>
  box_surfaces(const Point<dim>  &p0,
               const Point<dim>  &p1,
               const std::string &prefix);

  /**
   * An axis-parallel box [p0, p1] of uniform cells (n[d] along axis d); its
   * surfaces are box_surface_names(surface_prefix, dim).
   */
  template <int dim>
  BodyDefinition<dim>
  box_body(const std::string               &name,
           const Point<dim>                &p0,
           const Point<dim>                &p1,
           const std::vector<unsigned int> &n,
           const std::string               &surface_prefix);

  /** The same on the tensor grid of the step sizes steps[d] along axis d. */
  template <int dim>
  BodyDefinition<dim>
  box_body(const std::string                      &name,
           const Point<dim>                       &p0,
           const std::vector<std::vector<double>> &steps,
           const std::string                      &surface_prefix);

  /**
   * The box from p0 on the tensor grid `steps` (box_body()) with its bottom
   * moved onto the sphere of the given radius whose lowest point is
   * `lowest` (p0[1] = lowest[1]), the layers above in proportion: a cap
   * under a flat top. Surfaces: name_left, name_right, name_bottom (the
   * cap), name_top, name_front, name_back.
   */
  BodyDefinition<3>
  sphere_cap_body(const std::string                      &name,
                  const Point<3>                         &p0,
                  const std::vector<std::vector<double>> &steps,
                  const Point<3>                         &lowest,
                  const double                            radius);

  /**
   * A rectangle [p0, p1] on the tensor grid of the given step sizes; its
   * surfaces are name_left, name_right, name_bottom, name_top.
   */
  BodyDefinition<2>
  rectangle_body(const std::string         &name,
                 const Point<2>            &p0,
                 const Point<2>            &p1,
                 const std::vector<double> &x_steps,
                 const std::vector<double> &y_steps);

  /** The same with nx x ny uniform cells. */
  BodyDefinition<2>
  rectangle_body(const std::string &name,
                 const Point<2>    &p0,
                 const Point<2>    &p1,
                 const unsigned int nx,
                 const unsigned int ny);

  /**
   * A half-disc of radius R, arc downwards, of structured blocks: n45
   * elements along 45 degrees of arc, n_radial between the core and the arc.
   * A rectangle_height > 0 puts a rectangle of width 2R and n_up elements
   * in height on the diameter. Surfaces: name_arc, then name_sides and
   * name_top with a rectangle, name_top (the diameter) without.
   */
  BodyDefinition<2>
  half_disc_body(const std::string &name,
                 const Point<2>    &center,
                 const double       R,
                 const unsigned int n45,
                 const unsigned int n_radial,
                 const double       rectangle_height,
                 const unsigned int n_up);

  /**
   * A scene made of BodyDefinitions (every scene but 'gmsh'): its layout and
   * its mesh both come from bodies(). Element counts scale with the entry
   * Scene/Refinement factor.
   */
  template <int dim>
  class BuiltInScene : public SceneBase<dim>
  {
  public:
    /** A scene with no entries of its own. */
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    parse_parameters(ParameterHandler &prm) override;

    SceneLayout
    layout() const override
    {
      return layout_of(bodies());
    }

    void
    create_triangulation(Triangulation<dim> &triangulation) const override
    {
      mesh_bodies(bodies(), triangulation);
    }

  protected:
    /** Reads the scene's own entries (in subsection Scene). */
    virtual void
    parse_scene_parameters(ParameterHandler &)
    {}

    virtual std::vector<BodyDefinition<dim>>
    bodies() const = 0;

    /** An element count at the refinement factor. */
    unsigned int
    scaled(const double count) const
    {
      return MeshSteps::scaled(count, refinement_factor);
    }

    double refinement_factor; // Scene/Refinement factor
  };
} // namespace ContactDynamics

#endif
