// Persistency in long frictionless sliding: prm/ironing/mortar_persistency.prm
// (half the mesh density) to t = 3 s, 1 s of sliding at full depth:
// 'persistency' with a slightly dissipative Newmark scheme (gamma = 0.55,
// beta = (gamma + 1/2)^2 / 4). With the trapezoidal rule (gamma = 1/2) the
// multipliers of held nodes carry an undamped step-to-step alternation that
// the sliding pumps up (doc/contact.md, "Stabilization"): by 3 s it is
// 5 % of the pressure and the contact creates energy. Asserted, each from
// outside the solver's equations:
// - frictionless contact does no work while sliding: the contact work from
//   2 s to 3 s is below 0.1 % of the external work in that second;
// - a steadily sliding tool has no step-to-step alternation of its
//   pressure: at the monitored lowest tool node, the RMS of the second
//   difference / 4 (which is the amplitude of an alternation) over
//   2.5 s to 3 s is below 0.5 % of the mean pressure;
// - the penetration of every active node stays within that of its capture
//   step, dt/2 times the tool's approach speed 0.5 (plus 5 %);
// - no step is cut.
// The same with generalized-alpha (rho_inf = 0.8, second order) in place of
// Newmark gamma = 0.55: its persistency rates follow the scheme's beta and
// gamma, and its dissipation must damp the alternation as well.
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/simulator.h>

#include "tests.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace dealii;

namespace
{
  // `label`: the scheme, for the messages; `scheme`: its entries
  void
  check_long_sliding(const std::string &label, const ParameterChanges &scheme)
  {
    std::string directory = "output_long_sliding_" + label;
    std::replace(directory.begin(), directory.end(), ' ', '_');
    // snapshots of an earlier run would be read too
    std::filesystem::remove_all(directory);
    using Simulator          = ContactDynamics::Simulator<2>;
    const double     dt      = 0.01;
    double           deepest = 0;
    ParameterChanges changes{{"Scene/Refinement factor", "0.5"},
                             {"Time integration/End time", "3"},
                             {"Output/VTU interval", "10"},
                             {"Output/Output directory", directory}};
    changes.insert(changes.end(), scheme.begin(), scheme.end());
    const auto columns =
      run_shipped<Simulator>("prm/ironing/mortar_persistency.prm", changes);
    const auto history = read_csv_columns(directory + "/contact_history.csv");
    const auto check   = [&](const std::string &what, const bool ok) {
      check_true(label + ": " + what, ok);
    };
    const auto  &time   = columns.at("time");
    const auto  &work   = columns.at("contact_work");
    const auto  &ext    = columns.at("external_work");
    const double t_last = time.back();
    check("reaches t = 3", std::abs(t_last - 3) < 1e-9);
    check("no step cut", columns.at("time_step_cuts").back() == 0);

    // values at t = 2 (a step ends there)
    const auto at = [&](const std::vector<double> &y, const double t) {
      for (unsigned int i = 0; i < time.size(); ++i)
        if (std::abs(time[i] - t) < 1e-9)
          return y[i];
      AssertThrow(false, ExcMessage("no step at t = " + std::to_string(t)));
      return 0.;
    };
    const double sliding_work     = work.back() - at(work, 2);
    const double sliding_external = ext.back() - at(ext, 2);
    check("sliding: contact work below 0.1 % of the external work",
          std::abs(sliding_work) < 1e-3 * sliding_external);

    // the monitored node's pressure over 2.5 s to 3 s
    const auto &ht = history.at("time");
    const auto  pressure =
      std::find_if(history.begin(), history.end(), [](const auto &c) {
        return c.first.rfind("pressure", 0) == 0;
      });
    const auto gap =
      std::find_if(history.begin(), history.end(), [](const auto &c) {
        return c.first.rfind("gap", 0) == 0;
      });
    AssertThrow(pressure != history.end() && gap != history.end(),
                ExcMessage("contact_history.csv has no pressure/gap column"));
    const auto  &p    = pressure->second;
    double       mean = 0, alternation = 0;
    unsigned int n = 0;
    for (unsigned int i = 1; i + 1 < ht.size(); ++i)
      if (ht[i] > 2.5 - 1e-9)
        {
          mean += p[i];
          alternation += std::pow((p[i - 1] - 2 * p[i] + p[i + 1]) / 4, 2);
          ++n;
        }
    mean /= n;
    alternation = std::sqrt(alternation / n) / mean;
    check("sliding: no step-to-step alternation of the pressure (below "
          "0.5 % of the mean)",
          alternation < 5e-3);

    // every active node in every snapshot (every 10 steps), and the
    // monitored node at every step
    unsigned int snapshots = 0;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      if (entry.path().filename().string().rfind("contact_surface-", 0) == 0)
        {
          const auto surface = read_csv_columns(entry.path().string());
          for (unsigned int i = 0; i < surface.at("gap").size(); ++i)
            if (surface.at("active")[i] > 0)
              deepest = std::max(deepest, -surface.at("gap")[i]);
          ++snapshots;
        }
    check("snapshots read", snapshots >= 30);
    for (unsigned int i = 0; i < ht.size(); ++i)
      if (p[i] > 0)
        deepest = std::max(deepest, -gap->second[i]);
    check("penetration within dt/2 x approach speed 0.5 (+5 %)",
          deepest <= 1.05 * dt / 2 * 0.5);

    std::cout << label << ": sliding contact work " << sliding_work << " of "
              << sliding_external << ", alternation " << alternation
              << ", deepest " << deepest << std::endl;
  }
} // namespace

int
main()
{
  initlog();
  check_long_sliding("newmark gamma 0.55", {});
  // second order: generalized-alpha 0.8 instead of Newmark gamma 0.55
  check_long_sliding("generalized-alpha",
                     {{"Time integration/Scheme", "generalized-alpha"},
                      {"Time integration/Newmark beta", "0.25"},
                      {"Time integration/Newmark gamma", "0.5"}});
}
