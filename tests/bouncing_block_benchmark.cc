// The paper's bouncing block (section 5.1), shipped parameter files, first
// 3.6 s (the first contact and the release): stabilized mortar, static
// mortar and NTS.
// - First contact: the driven top u_y = 0.2 cos(pi t / 2) - 0.19 closes the
//   gap of 0.01 at t_kin = (2/pi) acos(0.95) = 0.202 s for a rigid block;
//   the bottom follows within one wave transit L/c = 1/sqrt(1e6/7750)
//   = 0.088 s, so contact starts in [t_kin, t_kin + L/c + dt].
// - Kinetic energy against the analytic motion of the driven block
//   (m = 7750 kg/m, v(t) = 0.1 pi sin(pi t / 2) the top's speed):
//   * before contact (t = 0.2 s) the free block follows its top almost
//     rigidly (wave transit 0.088 s against the drive's 4 s period):
//     KE = m v^2 / 2 = 36.5 J/m within 6 % (measured 35.5, -2.7 %: the
//     damped block lags its top slightly);
//   * in contact, the substrate (100 times stiffer) holds the block's
//     bottom while the top moves at v: the quasi-static block is uniformly
//     compressed, its vertical velocity linear in height, KE = m v^2 / 6,
//     127.5 J/m at the peak speed (t = 1 s and 3 s). The Poisson (lateral)
//     motion adds (nu/(1-nu))^2 / 4 = 4.6 % of it (plane strain, uniform
//     uniaxial stress, free sides; less with the top held in x), the
//     finite strain and the damped impact transient a few %: the peak
//     kinetic energy in contact
//     of stabilized mortar lies in [1, 1.15] m v_peak^2 / 6 (measured
//     140.9 = 1.105). The paper's figure 5 (kinetic energy, 0-300 J/m
//     scale; the rigid block at peak speed would have 382) only bounds it
//     loosely; a 2x error, or 10-20 % in the kinetic energy, fails here.
//   * the paper's finding (figure 5): without persistency (static mortar,
//     NTS) the release adds kinetic energy: their peak exceeds that of
//     stabilized mortar by more than 5 J/m (measured +10.6), and stays
//     bounded (below 1.3 m v_peak^2 / 6).
// - The energy balance closes once the contact work is counted (to 1e-4 of
//   the largest energy, the trapezoidal error on the neo-Hookean work).
// - The paper's finding: with persistency the contact never creates energy
//   (no step adds more than 0.1 J), without it (static mortar, NTS) the
//   release adds more than 10 J in one step.
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>

using namespace dealii;

int
main()
{
  initlog();
  const double dt = 0.025, t_kin = 2 / M_PI * std::acos(0.95),
               transit = 1 / std::sqrt(1e6 / 7750), m = 7750,
               v_peak = 0.1 * M_PI, ke_compressed = m * v_peak * v_peak / 6;
  double ke_stabilized = 0;
  for (const std::string variant :
       {"mortar_stabilized", "mortar_static", "nts"})
    {
      const auto s = run_shipped<ContactDynamics::Simulator<2>>(
        "prm/bouncing_block/" + variant + ".prm",
        {{"Time integration/End time", "3.6"},
         {"Output/Output directory", "output_" + variant},
         {"Output/VTU interval", "0"}});
      const auto  &time = s.at("time");
      const double t_c  = first_time_positive(s, "active_contact_nodes");
      deallog << variant << ": first contact at " << t_c << " s" << std::endl;
      check_true(variant + ": ran to 3.6 s",
                 std::abs(time.back() - 3.6) < 1e-9);
      check_true(variant + ": first contact in [t_kin, t_kin + L/c + dt]",
                 t_c >= t_kin && t_c <= t_kin + transit + dt);

      double ke_max = 0, e_max = 0, balance = 0, work_step = 0,
             ke_free = -1;
      for (unsigned int i = 0; i < time.size(); ++i)
        {
          if (std::abs(time[i] - 0.2) < 1e-9)
            ke_free = s.at("kinetic_energy")[i];
          if (time[i] > t_c - 1e-9)
            ke_max = std::max(ke_max, s.at("kinetic_energy")[i]);
          e_max =
            std::max(e_max,
                     s.at("kinetic_energy")[i] + s.at("elastic_energy")[i]);
          balance = std::max(balance,
                             std::abs(s.at("energy_balance_error")[i] -
                                      s.at("contact_work")[i]));
          if (i > 0)
            work_step =
              std::max(work_step,
                       s.at("contact_work")[i] - s.at("contact_work")[i - 1]);
        }
      check_true(variant + ": no NaN", std::isfinite(e_max + balance));
      const double v_free = 0.1 * M_PI * std::sin(M_PI / 2 * 0.2);
      check_range(variant + ": KE(0.2 s) / (m v^2 / 2) - 1 (free block)",
                  ke_free / (0.5 * m * v_free * v_free) - 1,
                  -0.06,
                  0.06);
      if (variant == "mortar_stabilized")
        {
          ke_stabilized = ke_max;
          check_range(variant + ": peak KE in contact / (m v_peak^2 / 6)",
                      ke_max / ke_compressed,
                      1.,
                      1.15);
        }
      else
        {
          check_range(variant + ": peak KE in contact - stabilized's (J/m)",
                      ke_max - ke_stabilized,
                      5.,
                      1e9);
          check_range(variant + ": peak KE in contact / (m v_peak^2 / 6)",
                      ke_max / ke_compressed,
                      1.,
                      1.3);
        }
      check_true(variant + ": energy balance closes with the contact work",
                 balance < 1e-4 * e_max);
      if (variant == "mortar_stabilized")
        check_true(variant + ": contact work never grows by 0.1 J in a step",
                   work_step < 0.1);
      else
        check_true(variant + ": the release creates more than 10 J",
                   work_step > 10);
    }
}
