#include <contact_dynamics/contact/node_state_fields.h>

namespace ContactDynamics
{
  namespace
  {
    using N = ContactNodeState;
    // (a bool is true above 0.5: exact for the 0 and 1 written)
    const std::vector<NodeStateField> fields{{"gap",
                                              [](const N &n) {
                                                return n.gap;
                                              },
                                              [](N &n, const double x) {
                                                n.gap = x;
                                              }},
                                             {"weight",
                                              [](const N &n) {
                                                return n.weight;
                                              },
                                              [](N &n, const double x) {
                                                n.weight = x;
                                              }},
                                             {"pressure",
                                              [](const N &n) {
                                                return n.pressure;
                                              },
                                              [](N &n, const double x) {
                                                n.pressure = x;
                                              }},
                                             {"tangential 1",
                                              [](const N &n) {
                                                return n.tangential[0];
                                              },
                                              [](N &n, const double x) {
                                                n.tangential[0] = x;
                                              }},
                                             {"tangential 2",
                                              [](const N &n) {
                                                return n.tangential[1];
                                              },
                                              [](N &n, const double x) {
                                                n.tangential[1] = x;
                                              }},
                                             {"slip rate 1",
                                              [](const N &n) {
                                                return n.slip_rate[0];
                                              },
                                              [](N &n, const double x) {
                                                n.slip_rate[0] = x;
                                              }},
                                             {"slip rate 2",
                                              [](const N &n) {
                                                return n.slip_rate[1];
                                              },
                                              [](N &n, const double x) {
                                                n.slip_rate[1] = x;
                                              }},
                                             {"projected",
                                              [](const N &n) {
                                                return double(n.projected);
                                              },
                                              [](N &n, const double x) {
                                                n.projected = x > 0.5;
                                              }},
                                             {"active",
                                              [](const N &n) {
                                                return double(n.active);
                                              },
                                              [](N &n, const double x) {
                                                n.active = x > 0.5;
                                              }},
                                             {"stick",
                                              [](const N &n) {
                                                return double(n.stick);
                                              },
                                              [](N &n, const double x) {
                                                n.stick = x > 0.5;
                                              }},
                                             {"persistent",
                                              [](const N &n) {
                                                return double(n.persistent);
                                              },
                                              [](N &n, const double x) {
                                                n.persistent = x > 0.5;
                                              }},
                                             {"gap rate",
                                              [](const N &n) {
                                                return n.gap_rate;
                                              },
                                              [](N &n, const double x) {
                                                n.gap_rate = x;
                                              }},
                                             {"gap acceleration",
                                              [](const N &n) {
                                                return n.gap_acceleration;
                                              },
                                              [](N &n, const double x) {
                                                n.gap_acceleration = x;
                                              }},
                                             {"velocity rate",
                                              [](const N &n) {
                                                return n.velocity_rate;
                                              },
                                              [](N &n, const double x) {
                                                n.velocity_rate = x;
                                              }},
                                             {"held gap",
                                              [](const N &n) {
                                                return n.held_gap;
                                              },
                                              [](N &n, const double x) {
                                                n.held_gap = x;
                                              }},
                                             {"held rate",
                                              [](const N &n) {
                                                return n.held_rate;
                                              },
                                              [](N &n, const double x) {
                                                n.held_rate = x;
                                              }},
                                             {"held acceleration",
                                              [](const N &n) {
                                                return n.held_acceleration;
                                              },
                                              [](N &n, const double x) {
                                                n.held_acceleration = x;
                                              }},
                                             {"reserved",
                                              [](const N &) {
                                                return 0.;
                                              },
                                              [](N &, const double) {}}};
  } // namespace

  const std::vector<NodeStateField> &
  node_state_fields()
  {
    return fields;
  }
} // namespace ContactDynamics
