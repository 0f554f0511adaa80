// Rigid obstacles: analytic surfaces (a plane, a cylinder - a circle in
// 2-D - or a sphere) that move by a prescribed rigid motion and act as the
// primary side of a contact pair, with no mesh and no unknowns. The
// geometry is templated on the number type: the formulations differentiate
// the signed distance and its normal with automatic differentiation.
#ifndef contact_dynamics_contact_rigid_obstacle_h
#define contact_dynamics_contact_rigid_obstacle_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /** The parameters of one obstacle: `Contact/Rigid obstacle <name>`. */
  struct RigidObstacleParameters
  {
    enum class Shape
    {
      plane,
      cylinder,
      sphere
    };

    std::string         name;
    Shape               shape = Shape::plane;
    std::vector<double> point, normal, axis, rotation_axis;
    double              radius = 1;
    // dim expressions of t, and one
    std::vector<std::string> translation;
    std::string              rotation_angle = "0";

    /** The subsection of an obstacle. */
    static std::string
    subsection_name(const std::string &name)
    {
      return "Rigid obstacle " + name;
    }

    /** Declares the entries of one obstacle's subsection. */
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int dim);

    /** Reads and checks them; messages name the subsection and entry. */
    void
    parse_parameters(ParameterHandler  &prm,
                     const unsigned int dim,
                     const std::string &name);
  };

  template <int dim>
  class RigidObstacle
  {
  public:
    using Shape = RigidObstacleParameters::Shape;

    /** Where the obstacle is at one time, and how it moves there. */
    struct Placement
    {
      Point<dim>     center;    // the obstacle's Point, moved
      Tensor<2, dim> rotation;  // from its orientation at t = 0
      Tensor<1, dim> direction; // the plane's normal or the cylinder's axis
      Tensor<1, dim> velocity;  // of the center
      Tensor<1, 3>   angular_velocity;
    };

    explicit RigidObstacle(const RigidObstacleParameters &parameters);

    const std::string &
    name() const
    {
      return parameters.name;
    }

    /**
     * The placement at time t (velocities by central differences); throws
     * if it is not finite.
     */
    Placement
    placement(const double t) const;

    /**
     * The signed distance of x to the surface (positive on the side of the
     * bodies) and its gradient, the unit normal that points to the bodies.
     */
    template <typename Number>
    Number
    signed_distance(const Placement              &where,
                    const Tensor<1, dim, Number> &x,
                    Tensor<1, dim, Number>       &normal) const
    {
      const Tensor<1, dim, Number> d = x - Tensor<1, dim, Number>(where.center);
      if (parameters.shape == Shape::plane)
        {
          for (unsigned int i = 0; i < dim; ++i)
            normal[i] = where.direction[i];
          return normal * d;
        }
      Tensor<1, dim, Number> radial = d;
      if (parameters.shape == Shape::cylinder && dim == 3)
        {
          const Number along = d * where.direction;
          for (unsigned int i = 0; i < dim; ++i)
            radial[i] -= along * where.direction[i];
        }
      using std::sqrt;
      const Number r = sqrt(radial * radial);
      normal         = radial / r;
      return r - parameters.radius;
    }

    /** The velocity of the obstacle's material point at y. */
    template <typename Number>
    Tensor<1, dim, Number>
    velocity(const Placement &where, const Tensor<1, dim, Number> &y) const
    {
      Tensor<1, dim, Number>       v;
      const Tensor<1, dim, Number> r = y - Tensor<1, dim, Number>(where.center);
      const auto                  &w = where.angular_velocity;
      if constexpr (dim == 2)
        {
          v[0] = where.velocity[0] - w[2] * r[1];
          v[1] = where.velocity[1] + w[2] * r[0];
        }
      else
        {
          v[0] = where.velocity[0] + w[1] * r[2] - w[2] * r[1];
          v[1] = where.velocity[1] + w[2] * r[0] - w[0] * r[2];
          v[2] = where.velocity[2] + w[0] * r[1] - w[1] * r[0];
        }
      return v;
    }

    /**
     * The obstacle's own bound on the depth a held node may sink before
     * the step is rejected: the radius, or for a plane none.
     */
    double
    depth() const
    {
      return parameters.shape == Shape::plane ? 1e300 : parameters.radius;
    }

    /**
     * How close to the axis or center of a cylinder or sphere a point
     * came that moved from x0 (obstacle at `from`) to x1 (at `to`): the
     * smallest distance along its straight path relative to the obstacle,
     * in the obstacle's own frame. A plane: infinity (it has no inside to
     * pass through).
     */
    double
    closest_approach(const Placement  &from,
                     const Placement  &to,
                     const Point<dim> &x0,
                     const Point<dim> &x1) const;

    /** The radius of a cylinder or sphere; 0 for a plane. */
    double
    radius() const
    {
      return parameters.shape == Shape::plane ? 0. : parameters.radius;
    }

  private:
    RigidObstacleParameters parameters;
    // the translation's components and the rotation angle, functions of t
    std::vector<std::shared_ptr<Function<1>>> translation;
    std::shared_ptr<Function<1>>              angle;
    Tensor<1, 3>                              rotation_axis;

    Tensor<2, dim>
    rotation(const double t) const;
  };
} // namespace ContactDynamics

#endif
