// Points in messages, "(x, y)" or "(x, y, z)", and as keys of maps.
#ifndef contact_dynamics_contact_coordinates_h
#define contact_dynamics_contact_coordinates_h

#include <deal.II/base/point.h>

#include <array>
#include <sstream>
#include <string>

namespace ContactDynamics
{
  using namespace dealii;

  /** "(x, y)" or "(x, y, z)", with the stream's default format. */
  template <int dim>
  std::string
  coordinates(const Point<dim> &x)
  {
    std::ostringstream out;
    out << '(';
    for (unsigned int d = 0; d < dim; ++d)
      out << (d > 0 ? ", " : "") << x[d];
    out << ')';
    return out.str();
  }

  /** The coordinates as a key of a map (nodes by reference position). */
  template <int dim>
  std::array<double, dim>
  position_key(const Point<dim> &x)
  {
    std::array<double, dim> key;
    for (unsigned int d = 0; d < dim; ++d)
      key[d] = x[d];
    return key;
  }
} // namespace ContactDynamics

#endif
