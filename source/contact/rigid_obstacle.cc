#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/rigid_obstacle.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ContactDynamics
{
  namespace
  {
    const Selection<RigidObstacleParameters::Shape> shape_names{
      {RigidObstacleParameters::Shape::plane, "plane"},
      {RigidObstacleParameters::Shape::cylinder, "cylinder"},
      {RigidObstacleParameters::Shape::sphere, "sphere"}};

    std::string
    zeros(const unsigned int dim, const std::string &separator)
    {
      std::string text = "0";
      for (unsigned int d = 1; d < dim; ++d)
        text += separator + "0";
      return text;
    }

    // a function of t from an expression, checked by evaluating it at t = 0
    std::shared_ptr<Function<1>>
    function_of_time(const std::string &expression, const std::string &where)
    {
      auto                 f = std::make_shared<FunctionParser<1>>(1);
      const SilencedStdErr silenced;
      try
        {
          f->initialize("t", expression, {{"pi", numbers::PI}});
          f->value(Point<1>(0.));
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcMessage(where + ": '" + expression +
                                 "' is not a function of t (FunctionParser "
                                 "syntax: sin, cos, pi, if(c,a,b), ...)."));
        }
      return f;
    }

    std::vector<double>
    unit_vector(const std::vector<double> &v, const std::string &where)
    {
      double norm = 0;
      for (const double x : v)
        norm += x * x;
      norm = std::sqrt(norm);
      AssertThrow(norm > 0,
                  ExcMessage(where + " is the zero vector; a direction is "
                                     "needed."));
      std::vector<double> unit = v;
      for (double &x : unit)
        x /= norm;
      return unit;
    }

    // R: the rotation with cosine c and sine s, in 2-D in the plane,
    void
    set_rotation(const double c,
                 const double s,
                 const Tensor<1, 3> &,
                 Tensor<2, 2> &R)
    {
      R[0][0] = c;
      R[0][1] = -s;
      R[1][0] = s;
      R[1][1] = c;
    }

    // in 3-D about the unit axis k (Rodrigues: c I + s [k]x + (1 - c) k k^T)
    void
    set_rotation(const double        c,
                 const double        s,
                 const Tensor<1, 3> &k,
                 Tensor<2, 3>       &R)
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          R[i][j] = (i == j ? c : 0.) + (1 - c) * k[i] * k[j];
      R[0][1] -= s * k[2];
      R[0][2] += s * k[1];
      R[1][0] += s * k[2];
      R[1][2] -= s * k[0];
      R[2][0] -= s * k[1];
      R[2][1] += s * k[0];
    }
  } // namespace

  void
  RigidObstacleParameters::declare_parameters(ParameterHandler  &prm,
                                              const unsigned int dim)
  {
    const RigidObstacleParameters defaults;
    const std::string             up = dim == 2 ? "0, 1" : "0, 1, 0";
    prm.declare_entry("Shape",
                      shape_names.name(defaults.shape),
                      shape_names.pattern(),
                      "The obstacle's surface: 'plane' (a line in 2-D), "
                      "'cylinder' (a circle in 2-D) or 'sphere' (3-D). The "
                      "obstacle fills the side of the surface away from "
                      "the bodies: below the plane, inside the cylinder or "
                      "sphere.");
    prm.declare_entry("Point",
                      zeros(dim, ", "),
                      Patterns::List(Patterns::Double(), dim, dim),
                      "At t = 0: a point of the plane, the center of the "
                      "circle or sphere, a point of the cylinder's axis. "
                      "The obstacle rotates about this point as it moves.");
    prm.declare_entry("Normal",
                      up,
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Plane: its normal at t = 0, pointing to the bodies "
                      "(any length but zero).");
    if (dim == 3)
      {
        prm.declare_entry("Axis",
                          "0, 0, 1",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "3-D cylinder: the direction of its axis at t = 0.");
        prm.declare_entry("Rotation axis",
                          "0, 0, 1",
                          Patterns::List(Patterns::Double(), 3, 3),
                          "3-D: the axis of the rotation 'Rotation angle', "
                          "through the moving Point.");
      }
    prm.declare_entry("Radius",
                      default_text(defaults.radius),
                      Patterns::Double(0),
                      "Cylinder (circle) and sphere: the radius, > 0.");
    prm.declare_entry("Translation",
                      zeros(dim, "; "),
                      Patterns::Anything(),
                      "The displacement of Point as functions of t, one per "
                      "coordinate separated by ';' (FunctionParser syntax, "
                      "with pi), zero at t = 0 unless the obstacle is to "
                      "start elsewhere. Its velocity (for friction and "
                      "persistency) is taken by central differences.");
    prm.declare_entry("Rotation angle",
                      defaults.rotation_angle,
                      Patterns::Anything(),
                      "The rotation (radians, counterclockwise about the "
                      "Rotation axis; in 2-D about z) as a function of t: "
                      "a rolling or spinning obstacle drags the bodies "
                      "through friction.");
  }

  void
  RigidObstacleParameters::parse_parameters(ParameterHandler  &prm,
                                            const unsigned int dim,
                                            const std::string &obstacle)
  {
    name                     = obstacle;
    const std::string where  = "In 'Contact/" + subsection_name(name) + "/";
    const auto        vector = [&](const std::string &entry) {
      return Utilities::string_to_double(
        Utilities::split_string_list(prm.get(entry)));
    };
    shape = shape_names.value(prm.get("Shape"));
    AssertThrow(!(dim == 2 && shape == Shape::sphere),
                ExcMessage(where +
                           "Shape' = sphere: a 2-D obstacle is a plane or a "
                           "cylinder (a circle)."));
    point         = vector("Point");
    normal        = unit_vector(vector("Normal"), where + "Normal'");
    axis          = dim == 3 ? unit_vector(vector("Axis"), where + "Axis'") :
                               std::vector<double>{0., 0., 1.};
    rotation_axis = dim == 3 ? unit_vector(vector("Rotation axis"),
                                           where + "Rotation axis'") :
                               std::vector<double>{0., 0., 1.};
    radius        = prm.get_double("Radius");
    AssertThrow(shape == Shape::plane || radius > 0,
                ExcMessage(where + "Radius' = " + prm.get("Radius") +
                           ": a cylinder or sphere needs a radius > 0."));
    translation = Utilities::split_string_list(prm.get("Translation"), ';');
    AssertThrow(translation.size() == dim,
                ExcMessage(where + "Translation' = '" + prm.get("Translation") +
                           "': " + std::to_string(dim) +
                           " expressions of t separated by ';' are needed."));
    for (const auto &e : translation)
      function_of_time(e, where + "Translation'");
    rotation_angle = prm.get("Rotation angle");
    function_of_time(rotation_angle, where + "Rotation angle'");
  }



  template <int dim>
  RigidObstacle<dim>::RigidObstacle(const RigidObstacleParameters &parameters)
    : parameters(parameters)
  {
    for (const auto &e : parameters.translation)
      translation.push_back(function_of_time(e, "Translation"));
    angle = function_of_time(parameters.rotation_angle, "Rotation angle");
    for (unsigned int d = 0; d < 3; ++d)
      rotation_axis[d] = parameters.rotation_axis[d];
  }

  template <int dim>
  Tensor<2, dim>
  RigidObstacle<dim>::rotation(const double t) const
  {
    const double   theta = angle->value(Point<1>(t));
    const double   c = std::cos(theta), s = std::sin(theta);
    Tensor<2, dim> R;
    set_rotation(c, s, rotation_axis, R);
    return R;
  }

  template <int dim>
  double
  RigidObstacle<dim>::closest_approach(const Placement  &from,
                                       const Placement  &to,
                                       const Point<dim> &x0,
                                       const Point<dim> &x1) const
  {
    if (parameters.shape == Shape::plane)
      return std::numeric_limits<double>::infinity();
    // the path relative to the center, without the component along a 3-D
    // cylinder's axis; a rotation about the center or the axis moves no
    // point of the surface in or out (undoing it would turn a node at rest
    // into a chord through the obstacle)
    const auto radial = [&](const Placement &where, const Point<dim> &x) {
      Tensor<1, dim> y = x - where.center;
      if (parameters.shape == Shape::cylinder && dim == 3)
        y -= (y * where.direction) * where.direction;
      return y;
    };
    const Tensor<1, dim> a = radial(from, x0), b = radial(to, x1), d = b - a;
    const double         s =
      d.norm_square() > 0 ? std::clamp(-(a * d) / d.norm_square(), 0., 1.) : 0.;
    return (a + s * d).norm();
  }

  template <int dim>
  typename RigidObstacle<dim>::Placement
  RigidObstacle<dim>::placement(const double t) const
  {
    Placement where;
    where.rotation = rotation(t);
    Tensor<1, dim> direction;
    for (unsigned int d = 0; d < dim; ++d)
      {
        where.center[d] =
          parameters.point[d] + translation[d]->value(Point<1>(t));
        direction[d] = parameters.shape == Shape::plane ? parameters.normal[d] :
                                                          parameters.axis[d];
      }
    where.direction = where.rotation * direction;
    // central differences (exact for motions quadratic in t); forward ones
    // at the start, where a motion may not be defined before t = 0
    const double h    = 1e-6 * std::max(1., std::abs(t));
    const double t0   = t - h < 0 ? t : t - h;
    const auto   rate = [&](const Function<1> &f) {
      return (f.value(Point<1>(t + h)) - f.value(Point<1>(t0))) / (t + h - t0);
    };
    for (unsigned int d = 0; d < dim; ++d)
      where.velocity[d] = rate(*translation[d]);
    where.angular_velocity = rotation_axis * rate(*angle);
    bool finite            = std::isfinite(where.angular_velocity.norm());
    for (unsigned int d = 0; d < dim; ++d)
      finite = finite && std::isfinite(where.center[d]) &&
               std::isfinite(where.velocity[d]) &&
               std::isfinite(where.direction[d]);
    // (every process places every obstacle: the same error on all)
    AssertThrow(finite,
                ExcCollective(
                  "The rigid obstacle '" + parameters.name +
                  "' has no finite position or velocity at t = " +
                  format_number(t) +
                  ": its Translation and Rotation angle (Contact/" +
                  RigidObstacleParameters::subsection_name(parameters.name) +
                  ") must be finite functions of t over the run."));
    return where;
  }

  template class RigidObstacle<2>;
  template class RigidObstacle<3>;
} // namespace ContactDynamics
