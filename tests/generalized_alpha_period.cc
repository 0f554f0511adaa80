// Free vibration with generalized-alpha and HHT-alpha against the schemes'
// analytical amplification. The one-element axial mode of newmark_period.cc
// (omega^2 = 3 E / (rho L^2), one free mode) is integrated by the code and,
// independently here, by the textbook recursion of the scheme on one degree
// of freedom (Chung and Hulbert 1993, eqs. 5-9; Hilber, Hughes and Taylor
// 1977) with alpha_m, alpha_f, beta, gamma from rho_inf:
//   (1 - am) a1 + am a0 + w^2 ((1 - af) u1 + af u0) = 0,
//   u1 = u0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),
//   v1 = v0 + dt ((1 - gamma) a0 + gamma a1).
// The period elongation and the amplitude decay per period of the measured
// motion are compared with the principal eigenvalue of the recursion's
// amplification matrix, whose spectral radius at omega dt -> infinity must
// be rho_inf; the energy the recursion's motion loses must appear as
// numerical_dissipation, with a closed energy balance. (Within a period the
// physical energy of a dissipative scheme's motion is not monotone: the
// dissipation is compared at the end only.)
#include <deal.II/lac/lapack_full_matrix.h>

#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <cmath>
#include <complex>

namespace
{
  struct Scheme
  {
    std::string name, scheme, rho, alpha_m, alpha_f;
    double      am, af; // from the published formulas, here
  };

  // (u, dt v, dt^2 a) -> the same one step later, for W = omega dt
  dealii::LAPACKFullMatrix<double>
  amplification(const double W, const double am, const double af)
  {
    const double gamma = 0.5 - am + af;
    const double beta  = 0.25 * (1 - am + af) * (1 - am + af);
    dealii::LAPACKFullMatrix<double> A(3, 3);
    for (unsigned int j = 0; j < 3; ++j)
      {
        const double u0 = j == 0, v0 = j == 1, a0 = j == 2;
        const double a1 =
          (-am * a0 - W * W * (u0 + (1 - af) * (v0 + (0.5 - beta) * a0))) /
          ((1 - am) + W * W * (1 - af) * beta);
        A(0, j) = u0 + v0 + (0.5 - beta) * a0 + beta * a1;
        A(1, j) = v0 + (1 - gamma) * a0 + gamma * a1;
        A(2, j) = a1;
      }
    return A;
  }

  std::vector<std::complex<double>>
  eigenvalues(dealii::LAPACKFullMatrix<double> A)
  {
    A.compute_eigenvalues();
    std::vector<std::complex<double>> lambda;
    for (unsigned int i = 0; i < 3; ++i)
      lambda.push_back(A.eigenvalue(i));
    return lambda;
  }
} // namespace

int
main()
{
  initlog();
  const double L     = AxialMode::L;
  const double omega = AxialMode::omega(), dt = AxialMode::dt();
  const double U = 0.002; // initial tip displacement

  const std::vector<Scheme> schemes{
    {"generalized-alpha rho_inf = 0.8",
     "generalized-alpha",
     "0.8",
     "",
     "",
     0.6 / 1.8,
     0.8 / 1.8},
    {"generalized-alpha rho_inf = 0", "generalized-alpha", "0", "", "", -1, 0},
    {"generalized-alpha rho_inf = 1",
     "generalized-alpha",
     "1",
     "",
     "",
     0.5,
     0.5},
    {"hht-alpha rho_inf = 0.8", "hht-alpha", "0.8", "", "", 0, 0.2 / 1.8},
    {"generalized-alpha alpha_m = 0.1, alpha_f = 0.3",
     "generalized-alpha",
     "",
     "0.1",
     "0.3",
     0.1,
     0.3}};

  for (const auto &s : schemes)
    {
      dealii::deallog << s.name << std::endl;
      dealii::ParameterHandler prm;
      read_axial_mode_parameters(
        "  set Scheme = " + s.scheme +
          (s.rho.empty() ? "" :
                           "\n  set Spectral radius at infinity = " + s.rho) +
          "\n  set Alpha m = " + s.alpha_m + "\n  set Alpha f = " + s.alpha_f,
        prm);
      std::ostringstream            screen;
      ContactDynamics::Simulator<2> simulator(prm, screen);
      simulator.initialize();
      const auto tip =
        vertex_dof(simulator.get_dof_handler(), dealii::Point<2>(L, 0), 0);

      // the recursion, from the consistent initial acceleration
      const auto             A = amplification(omega * dt, s.am, s.af);
      dealii::Vector<double> x(3), y(3);
      x[0]                                   = U;
      x[2]                                   = -omega * omega * U * dt * dt;
      const double        E0                 = simulator.energy().initial;
      double              largest_difference = 0;
      std::vector<double> u{simulator.displacement()(tip)};
      for (unsigned int n = 0; n < 200; ++n)
        {
          if (!simulator.advance(dt))
            check_true("step converged", false);
          A.vmult(y, x);
          x = y;
          u.push_back(simulator.displacement()(tip));
          largest_difference =
            std::max(largest_difference, std::abs(u.back() - x[0]));
        }
      check_close("tip displacement vs the scheme's recursion (relative to "
                  "U)",
                  largest_difference / U,
                  0,
                  1e-9);

      // measured: u_{n+1} = p u_n - q u_{n-1} fitted after step 60 (the
      // spurious root has decayed), p = 2 |lambda| cos(theta), q = |lambda|^2
      double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
      for (unsigned int n = 60; n + 1 < u.size(); ++n)
        {
          s11 += u[n] * u[n];
          s12 += -u[n] * u[n - 1];
          s22 += u[n - 1] * u[n - 1];
          r1 += u[n + 1] * u[n];
          r2 += -u[n + 1] * u[n - 1];
        }
      const double det             = s11 * s22 - s12 * s12;
      const double p               = (r1 * s22 - r2 * s12) / det,
                   q               = (s11 * r2 - s12 * r1) / det;
      const double radius_measured = std::sqrt(q);
      const double theta_measured  = std::acos(p / (2 * radius_measured));

      // the principal root: the complex pair
      std::complex<double> principal = 0;
      for (const auto &l : eigenvalues(A))
        if (std::imag(l) > std::imag(principal))
          principal = l;
      const double theta = std::arg(principal), radius = std::abs(principal);
      const double elongation = omega * dt / theta - 1;
      const double decay      = 1 - std::pow(radius, 2 * M_PI / theta);
      check_close("period elongation: measured vs amplification matrix",
                  omega * dt / theta_measured - 1,
                  elongation,
                  1e-7);
      check_close("amplitude decay per period: measured vs amplification "
                  "matrix",
                  1 - std::pow(radius_measured, 2 * M_PI / theta_measured),
                  decay,
                  1e-7);
      if (s.rho == "1" && s.alpha_m.empty())
        check_close("rho_inf = 1: period elongation vs the trapezoidal rule's "
                    "omega dt / (2 atan(omega dt / 2)) - 1",
                    elongation,
                    omega * dt / (2 * std::atan(omega * dt / 2)) - 1,
                    1e-10);
      dealii::deallog << "  omega dt = 2 pi / 20: period elongation "
                      << std::setprecision(4) << 100 * elongation
                      << " %, amplitude decay per period " << 100 * decay
                      << " %" << std::endl;

      // far above the resolved frequencies the amplification is rho_inf
      // (a triple root there: it splits like (omega dt)^(-2/3))
      double spectral_radius = 0;
      for (const auto &l : eigenvalues(amplification(1e12, s.am, s.af)))
        spectral_radius = std::max(spectral_radius, std::abs(l));
      if (s.alpha_m.empty())
        check_close("spectral radius at omega dt = 1e12 vs rho_inf",
                    spectral_radius,
                    std::stod(s.rho),
                    1e-6);
      else
        dealii::deallog << "  spectral radius at omega dt = 1e12: "
                        << spectral_radius << std::endl;

      // a numerical-dissipation column exactly for the schemes whose
      // amplification damps the highest frequencies
      {
        ContactDynamics::TimeIntegrator integrator;
        prm.enter_subsection("Time integration");
        integrator.parse_parameters(prm);
        prm.leave_subsection();
        dealii::deallog << "  numerical dissipation column "
                        << (integrator.is_dissipative() ? "written" : "omitted")
                        << ((spectral_radius < 1 - 1e-6) ==
                                integrator.is_dissipative() ?
                              ", as the spectral radius says" :
                              ", AGAINST the spectral radius")
                        << std::endl;
      }

      // the energy the recursion's motion lost (E ~ omega^2 u^2 + v^2) is
      // what the code reports as numerical dissipation
      const auto  &energy = simulator.energy();
      const double predicted =
        1 - (omega * omega * x[0] * x[0] + x[1] * x[1] / (dt * dt)) /
              (omega * omega * U * U);
      check_close("numerical dissipation / E_0 vs the recursion's energy loss",
                  energy.numerical / E0,
                  predicted,
                  1e-8);
      check_close("energy balance error / E_0", energy.error() / E0, 0, 1e-9);
    }
}
