#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <deal.II/numerics/vector_tools.h>

#include <contact_dynamics/contact/velocity_update.h>
#include <contact_dynamics/output/checkpoint.h>
#include <contact_dynamics/parameters.h>
#include <contact_dynamics/simulator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace ContactDynamics
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler  &prm,
                                     const SceneLayout &layout)
  {
    Scene<dim>::declare_parameters(prm);
    for (const auto &name : layout.body_names)
      {
        prm.enter_subsection(BodyParameters::subsection_name(name));
        BodyParameters::declare_parameters(prm, dim);
        prm.leave_subsection();
      }
    prm.enter_subsection("Finite element");
    Discretization<dim>::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    DirichletConditions<dim>::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Time integration");
    TimeIntegrator::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Nonlinear solver");
    NewtonSolver::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    OutputParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Energy watchdog");
    EnergyWatchdog::declare_parameters(prm);
    prm.leave_subsection();

    declare_contact_parameters(prm, layout, dim);

    prm.enter_subsection("Parallel");
    ParallelParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    RefinementParameters::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  const EnergyBalance &
  Simulator<dim>::energy() const
  {
    return energy_account.balance();
  }

  template <int dim>
  double
  Simulator<dim>::current_time() const
  {
    return time;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::n_steps() const
  {
    return step;
  }

  template <int dim>
  const DoFHandler<dim> &
  Simulator<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  const AffineConstraints<double> &
  Simulator<dim>::get_constraints() const
  {
    return increment_constraints;
  }

  template <int dim>
  const ContactFormulation<dim> *
  Simulator<dim>::get_contact() const
  {
    return contact.get();
  }

  template <int dim>
  const VectorType &
  Simulator<dim>::displacement() const
  {
    return u;
  }

  template <int dim>
  const VectorType &
  Simulator<dim>::velocity() const
  {
    return v;
  }

  template <int dim>
  parallel::TriangulationBase<dim> &
  Simulator<dim>::get_triangulation()
  {
    return *triangulation;
  }

  template <int dim>
  unsigned int
  Simulator<dim>::n_mesh_changes() const
  {
    return adaptation.n_mesh_changes();
  }

  template <int dim>
  bool
  Simulator<dim>::has_multipliers() const
  {
    return contact != nullptr;
  }

  template <int dim>
  double
  Simulator<dim>::iterate_norm() const
  {
    return u_new.l2_norm();
  }

  template <int dim>
  bool
  Simulator<dim>::balances_between_steps() const
  {
    return integrator.alpha_m() != 0 || integrator.alpha_f() != 0;
  }

  template <int dim>
  TrialState
  Simulator<dim>::trial_state() const
  {
    return {u_ghost,
            v_ghost,
            integrator.velocity_factor(controller.dt()),
            controller.dt(),
            integrator.is_dynamic(),
            integrator};
  }

  template <int dim>
  bool
  Simulator<dim>::is_held(const types::global_dof_index i) const
  {
    return held_dofs.is_element(i);
  }

  template <int dim>
  const VectorType &
  Simulator<dim>::ghosted(const VectorType &x, VectorType &ghost) const
  {
    if (ghost.size() != x.size())
      ghost.reinit(locally_owned, locally_relevant, mpi_communicator);
    ghost = x;
    return ghost;
  }

  template <int dim>
  std::ostream &
  Simulator<dim>::screen_log()
  {
    return pcout.is_active() ? pcout.get_stream() : null_stream;
  }

  template <int dim>
  void
  Simulator<dim>::set_trial_velocity_and_acceleration()
  {
    const double dt = controller.dt();
    auto         un = u_new.begin();
    auto         vn = v_new.begin();
    auto         an = a_new.begin();
    auto         uo = u.begin();
    auto         vo = v.begin();
    auto         ao = a.begin();
    for (; un != u_new.end(); ++un, ++vn, ++an, ++uo, ++vo, ++ao)
      integrator.update(dt, *uo, *vo, *ao, *un, *vn, *an);
  }

  template <int dim>
  double
  Simulator<dim>::apply_velocity_update()
  {
    const double work =
      integrator.is_dynamic() ? contact->velocity_update_request() : 0.;
    if (work == 0 || contact->velocity_update_force() == nullptr)
      return 0;
    TimerOutput::Scope t(*timer, "velocity update");
    return ContactDynamics::apply_velocity_update(*contact,
                                                  *mechanics,
                                                  dof_handler,
                                                  held_dofs,
                                                  bodies.size(),
                                                  work,
                                                  v_new);
  }
  template <int dim>
  void
  Simulator<dim>::assemble(const bool  with_jacobian,
                           VectorType &residual_out,
                           MatrixType &jacobian_out)
  {
    set_trial_velocity_and_acceleration();
    ghosted(u_new, u_ghost);
    ghosted(v_new, v_ghost);
    if (contact)
      {
        TimerOutput::Scope t(*timer, "contact search");
        if (contact->update_candidates(u_ghost))
          setup_sparsity();
      }
    TimerOutput::Scope t(*timer, "bulk assembly");
    const bool         balanced = balances_between_steps();
    if (balanced)
      compute_effective_acceleration();
    mechanics->assemble(u_ghost,
                        v_new,
                        balanced ? effective_acceleration : a_new,
                        integrator.effective_acceleration_factor(
                          controller.dt()),
                        integrator.velocity_factor(controller.dt()),
                        increment_constraints,
                        with_jacobian,
                        residual_out,
                        jacobian_out,
                        residual_full);
    t.stop();
    if (contact)
      {
        TimerOutput::Scope tc(*timer, "contact assembly");
        contact->assemble(trial_state(),
                          increment_constraints,
                          with_jacobian,
                          residual_out,
                          jacobian_out,
                          residual_full);
      }
    if (balanced)
      {
        // the forces of the committed state, contact included, weighted
        const double w = integrator.old_force_factor();
        residual_full.add(w, force_old);
        residual_out.add(w, force_old);
        increment_constraints.set_zero(residual_out);
      }
  }

  template <int dim>
  void
  Simulator<dim>::compute_effective_acceleration()
  {
    effective_acceleration = a_new;
    effective_acceleration.sadd(integrator.inertia_factor(),
                                integrator.old_inertia_factor(),
                                a);
  }

  template <int dim>
  void
  Simulator<dim>::compute_old_forces()
  {
    force_old.reinit(residual_full_old, true);
    mechanics->inertia_force(a, -1., force_old);
    force_old += residual_full_old;
    // the multiplier rows hold no forces
    for (const auto i : locally_owned)
      if (!displacement_dofs.is_element(i))
        force_old(i) = 0;
    force_old.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  Simulator<dim>::apply_update(const VectorType &du)
  {
    increment = du;
    if (any_hanging_nodes)
      increment_constraints.distribute(increment);
    else
      increment_constraints.set_zero(increment);
    u_new += increment;
  }

  template <int dim>
  std::vector<MultiplierGroup>
  Simulator<dim>::multiplier_groups() const
  {
    // a group's dofs are unknowns of this process (a vertex's dofs have one
    // owner); a multiplier held by a constraint is no unknown
    std::vector<MultiplierGroup> groups;
    for (auto group : contact->multiplier_groups())
      {
        auto &m = group.multipliers;
        m.erase(std::remove_if(m.begin(),
                               m.end(),
                               [&](const auto i) {
                                 return increment_constraints.is_constrained(i);
                               }),
                m.end());
        bool owned = true;
        for (const auto *dofs : {&group.displacements, &m})
          for (const auto i : *dofs)
            owned = owned && locally_owned.is_element(i);
        if (owned && !m.empty())
          groups.push_back(std::move(group));
      }
    return groups;
  }

  template <int dim>
  bool
  Simulator<dim>::jacobian_is_constant() const
  {
    return mechanics->is_linear() && !contact;
  }



  template <int dim>
  const MatrixType &
  Simulator<dim>::residual_and_jacobian(const VectorType &trial,
                                        const double      dt,
                                        VectorType       &residual_out)
  {
    controller.set_dt(dt);
    u_new = trial;
    if (balances_between_steps())
      compute_old_forces();
    assemble(true, residual_out, jacobian);
    structure_changed = true;
    return jacobian;
  }

  template <int dim>
  bool
  Simulator<dim>::advance(const double dt)
  {
    if (controller.begin_attempt(dt))
      structure_changed = true;
    const double t_new = time + dt;
    predict(t_new);
    const SolveResult solved  = solve(t_new);
    const StepVerdict verdict = evaluate(solved.newton);
    if (verdict.kind != StepVerdict::accept)
      {
        reject(verdict, solved, t_new);
        return false;
      }
    commit(solved.newton, t_new);
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::predict(const double t_new)
  {
    const double dt = controller.dt();
    auto         un = u_new.begin();
    auto         uo = u.begin();
    auto         vo = v.begin();
    auto         ao = a.begin();
    for (; un != u_new.end(); ++un, ++uo, ++vo, ++ao)
      *un = integrator.predict(dt, *uo, *vo, *ao);
    if (contact)
      for (const auto i : contact->multiplier_dofs())
        if (locally_owned.is_element(i))
          u_new(i) = u(i);
    u_new.compress(VectorOperation::insert);
    set_prescribed_values(u_new, t_new);

    if (contact)
      {
        contact->set_times(time, t_new);
        contact->start_step();
      }
  }

  template <int dim>
  typename Simulator<dim>::SolveResult
  Simulator<dim>::solve(const double t_new)
  {
    SolveResult solved;
    auto       &result = solved.newton;
    // of the passes before, on the meshes before
    unsigned int earlier_iterations = 0, earlier_linear_iterations = 0;
    for (unsigned int pass = 0;; ++pass)
      {
        if (balances_between_steps())
          compute_old_forces();
        {
          TimerOutput::Scope t(*timer, "Newton solve");
          result = newton.solve(*this,
                                jacobian,
                                residual,
                                increment,
                                structure_changed,
                                screen_log());
        }
        result.iterations += earlier_iterations;
        result.linear_iterations += earlier_linear_iterations;
        earlier_iterations        = result.iterations;
        earlier_linear_iterations = result.linear_iterations;
        // a mesh that follows the contact of this step, and the step again
        // on it from its transferred trial state
        if (!result.converged || !refinement.adapt_to_contact ||
            pass >= refinement.passes_per_step ||
            !adaptation.due_within(step + 1,
                                   contact ? contact->n_active_nodes() : 0) ||
            !adapt_mesh())
          break;
        solved.adapted    = true;
        structure_changed = true;
        set_prescribed_values(u_new, t_new);
        if (contact)
          {
            contact->set_times(time, t_new);
            contact->start_step();
          }
      }
    return solved;
  }

  template <int dim>
  StepVerdict
  Simulator<dim>::evaluate(const NewtonSolver::Result &result)
  {
    StepVerdict verdict;
    verdict.reason = result.failure;
    if (result.converged)
      {
        TimerOutput::Scope t(*timer, "energies");
        set_trial_velocity_and_acceleration();
        if (balances_between_steps())
          complete_balanced_forces();
        const std::string energies =
          energy_account.evaluate_step(*mechanics,
                                       state,
                                       u_ghost,
                                       increment_constraints,
                                       held_dofs,
                                       body_force,
                                       controller.dt(),
                                       contact ? contact->contact_work() : 0.,
                                       increment);
        if (!energies.empty())
          verdict.reason = energies;
        // DataOut evaluates the stresses at the nodes (with degree 1 the
        // corners; collective: on every process, whatever the failure)
        const std::string inverted = mechanics->inverted_corner(u_ghost);
        if (verdict.reason.empty())
          verdict.reason = inverted;
        // e.g. a node that went through a surface unnoticed
        if (verdict.reason.empty() && contact)
          verdict.reason = contact->check_step(u_ghost);
      }
    // adaptive time steps: the step is solved again with a smaller dt if
    // its local error is too large
    if (verdict.reason.empty() && result.converged &&
        integrator.error_tolerance() > 0)
      {
        verdict.reason = controller.judge_error(state,
                                                locally_owned,
                                                displacement_dofs,
                                                increment_constraints);
        if (!verdict.reason.empty())
          verdict.kind = StepVerdict::reject;
      }
    else if (!verdict.reason.empty() || !result.converged)
      verdict.kind = StepVerdict::cut;
    return verdict;
  }

  template <int dim>
  void
  Simulator<dim>::complete_balanced_forces()
  {
    // residual_full holds the balance between the steps (of the last
    // assembly, whose effective acceleration is still set); the reactions
    // and the next step need M a_{n+1} + F_{n+1}
    residual_full.add(-integrator.old_force_factor(), force_old);
    VectorType inertia(residual_full);
    increment = a_new;
    increment -= effective_acceleration;
    mechanics->inertia_force(increment, 1., inertia);
    residual_full += inertia;
  }

  template <int dim>
  void
  Simulator<dim>::reject(const StepVerdict &verdict,
                         const SolveResult &solved,
                         const double       t_new)
  {
    structure_changed = true;
    last_failure = verdict.reason.empty() ? "no convergence" : verdict.reason;
    if (solved.adapted)
      last_failure += " (on the mesh adapted to the step)";
    pcout << "  step to t = " << t_new << " with dt = " << controller.dt()
          << " failed: " << last_failure << std::endl;
    // an inexact linear solve that keeps Newton from converging on a
    // quasi-static problem is not helped by smaller steps (issue 39: 494
    // cuts in 180 s on prm/examples/hertz_adaptive.prm, before the cycle
    // damping recognized the cycle that caused them)
    if (!solved.newton.converged)
      ++failures_in_a_row;
    AssertThrow(integrator.is_dynamic() || linear_solver_name != "AMG" ||
                  failures_in_a_row < 3,
                ExcCollective(
                  "Newton did not converge in 3 attempts in a row at t = " +
                  format_number(time) + " (last: " + last_failure +
                  ", residual " + format_number(solved.newton.final_residual) +
                  ") with Nonlinear solver/Linear solver = AMG on a "
                  "quasi-static problem: Newton does not converge within "
                  "its Maximum iterations with the multigrid solves of the "
                  "condensed contact system here (see Linear tolerance), "
                  "and cutting the step does not change that. Use Linear "
                  "solver = KLU, MUMPS or auto "
                  "(auto takes a direct solver for quasi-static runs); if "
                  "that fails as well, a body is not held (quasi-static "
                  "needs every body held by Dirichlet conditions or "
                  "contact). The outputs up to the last step are "
                  "complete."));
  }

  template <int dim>
  void
  Simulator<dim>::commit(const NewtonSolver::Result &result, const double t_new)
  {
    failures_in_a_row = 0;
    if (contact)
      {
        // u_ghost: the converged state, as the last assembly saw it
        contact->commit_step(u_ghost, u, false);
        const double velocity_update = apply_velocity_update();
        energy_account.add_contact(velocity_update,
                                   contact->dissipated_energy(),
                                   contact->obstacle_work(),
                                   contact->contact_work());
      }
    history.commit(RunContext());
    time = t_new;
    ++step;
    structure_changed = false;
    controller.add_newton_iterations(result.iterations);
    linear_iterations = result.linear_iterations;
    output_step(result.iterations, result.final_residual, false);
  }

  template <int dim>
  void
  Simulator<dim>::set_prescribed_values(VectorType &x, const double t)
  {
    for (const auto &p :
         dirichlet.values(discretization.mapping(), dof_handler, t))
      if (locally_owned.is_element(p.first))
        x(p.first) = p.second;
    x.compress(VectorOperation::insert);
    if (any_hanging_nodes)
      hanging_constraints.distribute(x);
  }

  template <int dim>
  Tensor<1, dim>
  Simulator<dim>::reaction_force(const std::string &surface) const
  {
    const types::boundary_id id = layout.surface_id(surface);
    Tensor<1, dim>           force;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<bool> mask(discretization.fe().n_components(), false);
        mask[d] = true;
        for (const auto i : DoFTools::extract_boundary_dofs(dof_handler,
                                                            ComponentMask(mask),
                                                            {id}))
          if (is_held(i) && locally_owned.is_element(i))
            // the support balances the unconstrained residual there
            force[d] += residual_full_old(i);
      }
    return Utilities::MPI::sum(force, mpi_communicator);
  }

  template <int dim>
  void
  Simulator<dim>::stop_run(const std::string &reason,
                           const int          signal,
                           const std::string &epilogue)
  {
    // the last completed step's VTU files, if the interval skipped them
    const bool vtu = output_parameters.vtu_interval > 0;
    if (vtu && last_vtu_step != int(step))
      write_solution();
    std::ostringstream message;
    message << reason << " The run stops at step " << step << ", t = " << time
            << "; statistics.csv" << (contact ? ", contact_history.csv" : "")
            << (vtu ? " and the VTU files" : "") << " in '"
            << output_parameters.directory << "' are complete up to this step."
            << epilogue;
    if (signal != 0)
      AssertThrow(false, ExcStopped(message.str(), signal));
    AssertThrow(false, ExcCollective(message.str()));
  }

  template <int dim>
  void
  Simulator<dim>::stop_on_signal()
  {
    // SIGINT, SIGTERM: stop between steps, with complete outputs and a
    // checkpoint to continue from
    const int signal = stop_signal(mpi_communicator);
    if (signal == 0)
      return;
    if (last_checkpoint_step != int(step))
      write_checkpoint();
    stop_run(signal == SIGINT  ? "Interrupted (SIGINT)." :
             signal == SIGTERM ? "Terminated (SIGTERM)." :
                                 "Stopped by a signal.",
             signal,
             " A checkpoint of this step is in '" +
               Checkpoints::directory(output_parameters.directory, step) +
               "': 'contact-dynamics --restart " + output_parameters.directory +
               "' continues the run.");
  }

  template <int dim>
  void
  Simulator<dim>::after_accepted_step(const double dt_try)
  {
    // the mesh for the next step (without solving this one again; `step`
    // is the one just completed)
    if (refinement.adapt_to_contact && refinement.passes_per_step == 0 &&
        adaptation.due_after(step))
      adapt_mesh();
    controller.accepted(dt_try, screen_log());
    const unsigned int interval = output_parameters.checkpoint_interval;
    const double       minutes  = output_parameters.checkpoint_wall_time;
    // (the wall time of the first process decides for all)
    if ((interval > 0 && step % interval == 0) ||
        (minutes > 0 && Utilities::MPI::broadcast(mpi_communicator,
                                                  checkpoint_timer.wall_time(),
                                                  0) >= 60 * minutes))
      write_checkpoint();
  }

  template <int dim>
  void
  Simulator<dim>::after_failed_step(const double dt_try)
  {
    if (controller.rejected_by_estimate())
      {
        controller.rejected(dt_try, screen_log());
        return;
      }
    if (!controller.cut(dt_try))
      {
        // what the set-up warned about may be the cause
        const std::string caveats = contact ? contact->caveats() : "";
        stop_run("The time step would have to be cut to " +
                 format_number(controller.planned_dt()) +
                 " at t = " + format_number(time) +
                 ", below Time integration/Minimum time step = " +
                 format_number(integrator.minimum_time_step()) +
                 " (the last attempt: " + last_failure + ")." +
                 (caveats.empty() ? "" : " A likely cause: " + caveats));
      }
    pcout << "  cutting the time step to " << controller.planned_dt()
          << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::run(const std::string &checkpoint)
  {
    if (checkpoint.empty())
      initialize();
    else
      restart(checkpoint);
    const double time_step = integrator.time_step();
    const double end_time  = integrator.end_time();
    while (time < end_time - 1e-9 * time_step)
      {
        stop_on_signal();
        const double dt_try = controller.next_dt(end_time - time);
        if (advance(dt_try))
          after_accepted_step(dt_try);
        else
          after_failed_step(dt_try);
      }
    if (output_parameters.vtu_interval > 0 && last_vtu_step != int(step))
      write_solution();

    pcout << "Finished at t = " << time << " after " << step << " steps ("
          << controller.newton_iterations() << " Newton iterations, "
          << controller.n_cuts() << " time step cuts"
          << (integrator.error_tolerance() > 0 ?
                ", " + std::to_string(controller.n_rejected()) +
                  " steps rejected by the error estimate" :
                std::string())
          << "). Results are in '" << output_parameters.directory << "'."
          << std::endl;
    timer->print_summary();
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace ContactDynamics
