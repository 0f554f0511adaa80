// SurfaceContact: the complementarity conditions of the secondary nodes
// (normal contact with its stabilizations; friction in
// surface_contact_friction.cc) and the assembly of the
// patches' forces and the nodal sums they depend on.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/node_state_fields.h>
#include <contact_dynamics/contact/surface_contact.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ContactDynamics
{
  namespace
  {
    // the two-valued selections parse into bools
    using Stabilization = ComplementarityParameters::Stabilization;
    const Selection<Stabilization> stabilization_names{
      {Stabilization::persistency, "persistency"},
      {Stabilization::velocity_persistency, "velocity persistency"},
      {Stabilization::velocity_update, "velocity update"},
      {Stabilization::none, "none"}};
    const Selection<bool> jacobian_names{{true, "exact"},
                                         {false, "approximate"}};
  } // namespace

  void
  ComplementarityParameters::declare_parameters(
    ParameterHandler                &prm,
    const ComplementarityParameters &defaults)
  {
    prm.declare_entry("c_n",
                      default_text(defaults.c_n),
                      Patterns::Double(1e-300),
                      "Complementarity constant c_n > 0 in C_j = lambda_j - "
                      "max(0, lambda_j - c_n g_j). It changes the Newton "
                      "path, not the solution; pick it within a few orders "
                      "of magnitude of E / h (stress / length).");
    prm.declare_entry("Normalize c_n",
                      default_text(defaults.normalize_c_n),
                      Patterns::Bool(),
                      "Mortar: divide the weighted gap by the nodal weight "
                      "integral(N_j) over the covered segments, so that c_n "
                      "does not depend on the mesh size (units stress / "
                      "length). The node-to-segment gap is a length already.");
    prm.declare_entry(
      "Stabilization",
      stabilization_names.name(defaults.stabilization),
      stabilization_names.pattern(),
      "What keeps contact from creating energy. 'persistency': a node in "
      "contact at the end of the previous step (gap <= Capture tolerance) "
      "enforces a zero Newmark rate of its normalized weighted gap, "
      "gdot_{n+1} = gamma/(beta dt) (g_{n+1} - g_n) + (terms of step n), "
      "with g the gap of the whole discretization (moving segments, "
      "rotating normals, changing Jacobians), so a held penetration stays "
      "constant to solver tolerance and frictionless contact does no work "
      "up to the time discretization. In long curved sliding it needs "
      "Newmark gamma > 1/2 (e.g. 0.55): with the trapezoidal rule the held "
      "multipliers' step-to-step alternation is undamped and grows. "
      "'velocity persistency': the paper's velocity-level condition -int "
      "psi (v_s - v_p).n = 0, exact on flat surfaces only (drift on curved "
      "sliding ones). 'velocity update': as 'persistency', then after each "
      "step one factor on the free velocities of the bodies the contact "
      "acted on returns the step's normal contact work to kinetic energy "
      "(a projection after Hairer, Lubich and Wanner, IV.4): impacts of "
      "free elastic bodies keep their energy exactly; it changes momentum, "
      "is worse than 'persistency' with Rayleigh damping and at the "
      "lift-off of driven bodies (chatter), and stops the bodies when they "
      "carry less kinetic energy than the work to return (doc/contact.md). "
      "'none': the gap is enforced at every step ('static').");
    prm.declare_entry("Capture tolerance",
                      default_text(defaults.capture_tolerance),
                      Patterns::Double(0),
                      "A node whose (normalized) gap, in length units, is at "
                      "most this value at the end of a step counts as in "
                      "contact for the persistency condition of the next "
                      "step (>= 0, at most a tenth of the shortest face of "
                      "the contact surfaces).");
    prm.declare_entry(
      "Capture",
      "rate",
      Patterns::Selection("rate|position"),
      "How a node held by 'persistency' or 'velocity update' starts: "
      "'rate' (default): its first held step starts from the gap rate it "
      "was captured with, so it sinks by dt/2 times that rate and is held "
      "there (energy-consistent at impacts). 'position': it starts at rest, "
      "so it keeps the gap it was captured with. Measured (doc/contact.md, "
      "'Capture'): on the ironing, no capture transient, no pressure at a "
      "distance and 29 % less pressure roughness for 3.5 % more Newton "
      "iterations; at impacts it creates energy (bar impact: 8.3 times the "
      "initial energy after 3 s): for slow or sliding contact only.");
    prm.declare_entry("c_t",
                      default_text(defaults.c_t),
                      Patterns::Double(1e-300),
                      "Friction complementarity constant c_t > 0 (paper "
                      "equation 8): decides stick or slip from lambda_t + c_t "
                      "v_t with the (normalized) relative tangential velocity "
                      "v_t; like c_n it changes the Newton path, not the "
                      "solution. Units stress x time / length; c_n dt is a "
                      "good start.");
    prm.declare_entry("Jacobian",
                      jacobian_names.name(defaults.exact_jacobian),
                      jacobian_names.pattern(),
                      "'exact': automatic differentiation through normals, "
                      "projections and segment end points. 'approximate': "
                      "those geometric derivatives are dropped, as in the "
                      "paper's code (more Newton iterations).");
  }

  void
  ComplementarityParameters::parse_parameters(ParameterHandler &prm)
  {
    c_n                 = prm.get_double("c_n");
    normalize_c_n       = prm.get_bool("Normalize c_n");
    stabilization       = stabilization_names.value(prm.get("Stabilization"));
    capture_tolerance   = prm.get_double("Capture tolerance");
    capture_at_position = prm.get("Capture") == "position";
    // (checked by the formulation that uses it: SurfaceContact)
    exact_jacobian = jacobian_names.value(prm.get("Jacobian"));
    c_t            = prm.get_double("c_t");
  }


  template <int dim>
  void
  SurfaceContact<dim>::assemble(const TrialState                &state,
                                const AffineConstraints<double> &constraints,
                                const bool                       with_jacobian,
                                VectorType                      &residual,
                                MatrixType                      &jacobian,
                                VectorType                      &residual_full)
  {
    work.start_assembly();
    n_stick = n_slip = 0;
    n_active         = 0;
    std::fill(std::begin(total_force), std::end(total_force), 0.);
    for (auto &pair : pairs)
      pair.reaction = {};
    const LinearSystem system{constraints,
                              with_jacobian,
                              residual,
                              jacobian,
                              residual_full,
                              hanging};
    // (every pair's sums exist before any patch can fail: the exchange
    // runs anyway)
    for (auto &pair : pairs)
      {
        const unsigned int n_nodes = pair.secondary.n_nodes();
        pair.gap.assign(n_nodes, LinearizedValue());
        pair.weight.assign(n_nodes, LinearizedValue());
        pair.gap_rate.assign(n_nodes, LinearizedValue());
        pair.slip_rate.assign(n_nodes, {});
      }
    run_collectively(
      comm,
      [&]() {
        for (auto &pair : pairs)
          {
            assemble_patches(pair, state, system);
            move_hanging_sums(pair);
          }
      },
      [&]() {
        for (auto &pair : pairs)
          exchange_node_sums(pair);
      });
    run_collectively(
      comm,
      [&]() {
        for (auto &pair : pairs)
          assemble_nodes(pair, state, system);
      },
      [&]() {
        finish_assembly(system);
      });
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_patches(PairData           &pair,
                                        const TrialState   &state,
                                        const LinearSystem &system)
  {
    for (unsigned int p = 0; p < n_patches(pair); ++p)
      if (pair.assembled_patch[p])
        {
          PatchForces forces;
          if (!pair.obstacle)
            assemble_patch(pair, p, state, forces);
          else if (!pair.candidates[p].empty())
            {
              assemble_obstacle_patch(pair, p, state, forces);
              obstacles.add_reaction(pair, forces, state.u);
            }
          add_forces(forces, system);
        }
  }

  template <int dim>
  void
  SurfaceContact<dim>::add_forces(const PatchForces  &forces,
                                  const LinearSystem &system)
  {
    // the force on a hanging node acts on the nodes it follows (C^T f)
    std::vector<std::pair<types::global_dof_index, double>> to(1);
    const auto targets = [&](const types::global_dof_index row)
      -> const std::vector<std::pair<types::global_dof_index, double>> & {
      if (const auto *h = hanging.find(row))
        return *h;
      to[0] = {row, 1.};
      return to;
    };
    for (const auto &r : forces.rows)
      for (const auto &[row, weight] : targets(r.row))
        {
          system.residual_full(row) += weight * r.value;
          work.add_force(row, weight * r.value);
          if (system.constraints.is_constrained(row))
            continue;
          system.residual(row) += weight * r.value;
          if (system.with_jacobian)
            system.add_row(row, r.derivatives, weight);
        }
    for (const auto &t : forces.tangential)
      for (const auto &[row, weight] : targets(t.first))
        work.add_friction_force(row, weight * t.second);
  }

  template <int dim>
  void
  SurfaceContact<dim>::exchange_node_sums(PairData &pair) const
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // per node: its index, then per quantity the value and the derivatives
    std::map<unsigned int, Message> outgoing;
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (!pair.owned_node[j])
        {
          const auto quantities = pair.node_sums(j);
          if (std::all_of(quantities.begin(), quantities.end(), [](auto *q) {
                return q->value == 0 && q->derivatives.empty();
              }))
            continue;
          auto &message = outgoing[pair.node_owner[j]];
          message.write_index(j);
          for (LinearizedValue *q : quantities)
            {
              message.write(q->value);
              message.write_sparse(q->derivatives);
              *q = LinearizedValue();
            }
        }
    send_messages(comm, outgoing, [&](Message &received) {
      while (!received.at_end())
        {
          const unsigned int j = received.read_index();
          Assert(pair.owned_node[j], ExcInternalError());
          for (LinearizedValue *q : pair.node_sums(j))
            {
              q->value += received.read();
              received.add_sparse(q->derivatives);
            }
        }
    });
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_nodes(PairData           &pair,
                                      const TrialState   &state,
                                      const LinearSystem &system)
  {
    for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
      if (pair.owned_node[j])
        {
          LinearizedValue constraint;
          const bool      active =
            assemble_normal(pair, j, state, system, constraint);
          // a constrained normal row has no friction row either
          if (pair.friction_coefficient > 0 &&
              !system.constraints.is_constrained(pair.secondary.dofs[j][dim]))
            assemble_friction(pair, j, active, constraint, state.u, system);
        }
  }

  template <int dim>
  LinearizedValue
  SurfaceContact<dim>::held_gap_rate(PairData          &pair,
                                     const unsigned int j,
                                     const TrialState  &state) const
  {
    // the Newmark rate of the normalized gap g/w, from its committed value
    // and rates, times c_n dt; unnormalized: times w (c_n dt w gdot)
    NodeState   &node  = pair.nodes[j];
    const auto  &g     = pair.gap[j];
    const auto  &w     = pair.weight[j];
    const double ratio = g.value / w.value;
    const double c     = complementarity.c_n * state.dt;
    state.integrator.update(state.dt,
                            node.held_gap,
                            node.held_rate,
                            node.held_acceleration,
                            ratio,
                            node.gap_rate,
                            node.gap_acceleration);
    const double    scale = complementarity.normalize_c_n ? 1. : w.value;
    LinearizedValue rate;
    rate.value = c * scale * node.gap_rate;
    // d(g/w) = dg / w - g dw / w^2
    for (const auto &d : g.derivatives)
      rate.derivatives[d.first] += c * scale * state.c_v * d.second / w.value;
    for (const auto &d : w.derivatives)
      rate.derivatives[d.first] -=
        c * scale * state.c_v * ratio * d.second / w.value;
    if (!complementarity.normalize_c_n)
      for (const auto &d : w.derivatives)
        rate.derivatives[d.first] += c * node.gap_rate * d.second;
    return rate;
  }

  template <int dim>
  bool
  SurfaceContact<dim>::assemble_normal(PairData           &pair,
                                       const unsigned int  j,
                                       const TrialState   &state,
                                       const LinearSystem &system,
                                       LinearizedValue    &constraint)
  {
    // the complementarity condition, scaled by the node's reference weight
    // so that its row has force units
    NodeState                    &node   = pair.nodes[j];
    const types::global_dof_index row    = pair.secondary.dofs[j][dim];
    const double                  scale  = pair.secondary.reference_weight[j];
    const double                  lambda = state.u(row);
    node.pressure = lambda * traction_per_multiplier(pair, j, state.u);
    node.gap      = pair.gap[j].value;
    node.weight   = pair.weight[j].value;
    // a node counts once the formulation's coverage rule lets it
    node.projected = node.weight > minimum_coverage() * scale;

    // the constraint quantity c * g / w (or its rate) and its derivatives
    bool active = false;
    if (node.projected)
      {
        const bool normalize = complementarity.normalize_c_n;
        const bool held      = node.persistent && state.dynamic;
        const auto rates     = complementarity.stabilization;
        node.velocity_rate   = pair.gap_rate[j].value / node.weight;
        if (held && rates != Stabilization::velocity_persistency)
          constraint = held_gap_rate(pair, j, state);
        else
          {
            const bool velocity =
              held && rates == Stabilization::velocity_persistency;
            const LinearizedValue &g =
              velocity ? pair.gap_rate[j] : pair.gap[j];
            const double factor =
              complementarity.c_n * (velocity ? state.dt : 1.);
            const double w   = normalize ? node.weight : 1.;
            constraint.value = factor * g.value / w;
            for (const auto &d : g.derivatives)
              constraint.derivatives[d.first] += factor * d.second / w;
            if (normalize)
              for (const auto &d : pair.weight[j].derivatives)
                constraint.derivatives[d.first] -=
                  factor * g.value * d.second / (w * w);
            node.gap_rate         = node.velocity_rate;
            node.gap_acceleration = 0;
          }
        active = (lambda - constraint.value > 0);
      }
    node.active = active;
    n_active += active;
    if (system.constraints.is_constrained(row))
      return active;
    if (active)
      {
        system.residual(row) += scale * constraint.value;
        if (system.with_jacobian)
          system.add_row(row, constraint.derivatives, scale);
      }
    else
      {
        system.residual(row) += scale * lambda;
        if (system.with_jacobian)
          system.jacobian.add(row, row, scale);
      }
    return active;
  }

  template <int dim>
  void
  SurfaceContact<dim>::finish_assembly(const LinearSystem &system)
  {
    system.residual.compress(VectorOperation::add);
    system.residual_full.compress(VectorOperation::add);
    if (system.with_jacobian)
      system.jacobian.compress(VectorOperation::add);
    work.compress();
    const VectorType &force = work.trial_force();

    for (const auto &pair : pairs)
      for (const auto &node_dofs : pair.secondary.dofs)
        for (unsigned int d = 0; d < dim; ++d)
          if (owned_dofs.is_element(node_dofs[d]))
            total_force[d] -= force(node_dofs[d]);
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        ProcessSums sums;
        for (double &f : total_force)
          sums.add(f);
        sums.add(n_active);
        sums.add(n_stick);
        sums.add(n_slip);
        obstacles.add_to_sums(sums);
        sums.sum(comm);
        gather_node_states();
      }
  }

  template <int dim>
  void
  SurfaceContact<dim>::gather_node_states()
  {
    // each node's state comes from the process that owns it; a sum over
    // processes of the owned entries (zeros elsewhere) gathers them
    const auto         &fields = node_state_fields();
    std::vector<double> data;
    for (const auto &pair : pairs)
      for (unsigned int j = 0; j < pair.nodes.size(); ++j)
        for (unsigned int f = 0; f < n_output_node_fields; ++f)
          data.push_back(pair.owned_node[j] ? fields[f].get(pair.nodes[j]) :
                                              0.);
    Utilities::MPI::sum(data, comm, data);
    auto x = data.begin();
    for (auto &pair : pairs)
      for (auto &n : pair.nodes)
        for (unsigned int f = 0; f < n_output_node_fields; ++f)
          fields[f].set(n, *x++);
  }

#define INSTANTIATE(dim)                                                     \
  template void SurfaceContact<dim>::assemble(                               \
    const TrialState &,                                                      \
    const AffineConstraints<double> &,                                       \
    const bool,                                                              \
    VectorType &,                                                            \
    MatrixType &,                                                            \
    VectorType &);                                                           \
  template void SurfaceContact<dim>::assemble_patches(PairData &,            \
                                                      const TrialState &,    \
                                                      const LinearSystem &); \
  template void SurfaceContact<dim>::add_forces(const PatchForces &,         \
                                                const LinearSystem &);       \
  template void SurfaceContact<dim>::exchange_node_sums(PairData &) const;   \
  template void SurfaceContact<dim>::assemble_nodes(PairData &,              \
                                                    const TrialState &,      \
                                                    const LinearSystem &);   \
  template LinearizedValue SurfaceContact<dim>::held_gap_rate(               \
    PairData &,                                                              \
    const unsigned int,                                                      \
    const TrialState &) const;                                               \
  template bool SurfaceContact<dim>::assemble_normal(PairData &,             \
                                                     const unsigned int,     \
                                                     const TrialState &,     \
                                                     const LinearSystem &,   \
                                                     LinearizedValue &);     \
  template void SurfaceContact<dim>::finish_assembly(const LinearSystem &);  \
  template void SurfaceContact<dim>::gather_node_states();

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
