// Period of a one-element axial mode against the analytical period with
// Newmark's known period elongation. A Q1 element [0,L]x[0,h] (nu = 0) is
// clamped on its left side and can only move axially on its right side;
// u_x = U x/L gives stiffness k = E h/L and consistent mass m = rho h L/3,
// so omega^2 = 3 E/(rho L^2). The trapezoidal rule (beta = 1/4,
// gamma = 1/2) keeps the amplitude and has the discrete frequency
// Omega = 2/dt atan(omega dt/2), i.e. the period elongates by
// T_num/T = (omega dt/2)/atan(omega dt/2).
#include <deal.II/dofs/dof_handler.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>

int
main()
{
  initlog();
  const double L     = AxialMode::L;
  const double omega = AxialMode::omega(), dt = AxialMode::dt();
  const double T = 2 * M_PI / omega;

  dealii::ParameterHandler prm;
  read_axial_mode_parameters("", prm);
  std::ostringstream            screen;
  ContactDynamics::Simulator<2> simulator(prm, screen);
  simulator.initialize();

  // x displacement of the vertex (L, 0)
  const auto tip =
    vertex_dof(simulator.get_dof_handler(), dealii::Point<2>(L, 0), 0);

  // For u_n = U cos(Omega n dt): u_{n+1} + u_{n-1} = 2 cos(Omega dt) u_n;
  // fit cos(Omega dt) by least squares over 200 steps.
  std::vector<double> u{simulator.displacement()(tip)};
  for (unsigned int n = 0; n < 200; ++n)
    {
      if (!simulator.advance(dt))
        check_true("step converged", false);
      u.push_back(simulator.displacement()(tip));
    }
  double num = 0, den = 0, amplitude = 0;
  for (unsigned int n = 1; n + 1 < u.size(); ++n)
    {
      num += (u[n + 1] + u[n - 1]) * u[n];
      den += 2 * u[n] * u[n];
    }
  for (const double x : u)
    amplitude = std::max(amplitude, std::abs(x));
  const double T_measured = 2 * M_PI * dt / std::acos(num / den);
  const double elongation =
    (omega * dt / 2) / std::atan(omega * dt / 2); // T_newmark / T

  check_close("amplitude preserved (relative)", amplitude / 0.002, 1., 1e-9);
  check_close("measured period / Newmark period",
              T_measured / (T * elongation),
              1.,
              1e-8);
  check_close("measured period elongation vs (omega dt)^2/12 to O(dt^4)",
              T_measured / T - 1,
              std::pow(omega * dt, 2) / 12,
              2e-4);
  dealii::deallog << "period elongation at dt = T/20: " << std::setprecision(3)
                  << 100 * (elongation - 1) << " %" << std::endl;
}
