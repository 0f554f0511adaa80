// The Simulator's mesh adaptation: refinement near the contact zone and
// the transfer of the state to the new mesh.
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
  bool
  Simulator<dim>::adapt_mesh()
  {
    {
      TimerOutput::Scope t(*timer, "mesh adaptation");
      // u_ghost: the trial state of the last assembly
      const std::vector<Point<dim>> zone =
        contact ?
          contact->contact_zone(u_ghost,
                                refinement.lookahead_steps * controller.dt()) :
          std::vector<Point<dim>>();
      const unsigned int dropped = mark_cells_near_contact(dof_handler,
                                                           u_ghost,
                                                           zone,
                                                           refinement,
                                                           base_level);
      if (adaptation.cell_limit_reached(dropped))
        pcout << "  Mesh refinement/Maximum cells = "
              << refinement.maximum_cells << " reached at t = " << time << ": "
              << dropped
              << " cells near the contact are not refined (reported once)"
              << std::endl;
    }
    return refine_and_transfer();
  }

  template <int dim>
  bool
  Simulator<dim>::refine_and_transfer()
  {
    auto *tria = dynamic_cast<parallel::distributed::Triangulation<dim> *>(
      triangulation.get());
    AssertThrow(tria != nullptr,
                ExcMessage(
                  "Mesh refinement needs Parallel/Mesh = distributed."));
    TimerOutput::Scope t(*timer, "mesh adaptation");
    tria->prepare_coarsening_and_refinement();
    if (!any_cell_flagged(*tria, mpi_communicator))
      return false;

    const double energy_before = energy_account.before_mesh_change();
    // the velocity that coarsening would interpolate: its projection keeps
    // the momenta and cannot add kinetic energy (the multipliers and the
    // prescribed values stay)
    {
      std::vector<bool> extra(discretization.fe().n_components(), true);
      for (unsigned int d = 0; d < dim; ++d)
        extra[d] = false;
      IndexSet fixed =
        union_over_processes(DoFTools::extract_dofs(dof_handler,
                                                    ComponentMask(extra)),
                             mpi_communicator);
      fixed.add_indices(dirichlet_dofs);
      project_before_coarsening(dof_handler,
                                mechanics->mass_matrix(),
                                hanging_constraints,
                                fixed,
                                v);
    }
    const auto cells_before    = tria->n_global_active_cells();
    const auto unknowns_before = dof_handler.n_dofs();
    // the committed state and the trial state of the step, and the mean
    // acceleration of the last step for the time-step error estimate
    std::vector<VectorType *>       moved = history.prepare_transfer();
    std::vector<VectorType>         old(moved.size());
    std::vector<const VectorType *> old_pointers;
    for (unsigned int i = 0; i < moved.size(); ++i)
      old_pointers.push_back(&ghosted(*moved[i], old[i]));
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    transfer.prepare_for_coarsening_and_refinement(old_pointers);
    tria->execute_coarsening_and_refinement();
    t.stop();

    setup_system(false);
    transfer.interpolate(moved);
    for (VectorType *x : moved)
      {
        // the unused multipliers (interpolated next to surface nodes)
        for (const auto i : held_dofs &locally_owned)
          if (!dirichlet_dofs.is_element(i))
            (*x)(i) = 0;
        x->compress(VectorOperation::insert);
        if (any_hanging_nodes)
          hanging_constraints.distribute(*x);
      }
    set_prescribed_values(u, time);
    set_prescribed_values(u_new, time + controller.dt());
    reevaluate_committed_state();
    if (integrator.is_dynamic())
      {
        // the acceleration the equation of motion gives on the new mesh:
        // Newmark keeps the energy only from a balanced state
        VectorType correction(residual_full_old), mass_correction(a);
        correction *= -1;
        condense_rows(increment_constraints, correction);
        solve_constrained_mass_system(mechanics->mass_matrix(),
                                      increment_constraints,
                                      correction);
        a += correction;
        mechanics->mass_matrix().vmult(mass_correction, correction);
        residual_full_old += mass_correction;
      }

    ghosted(u, u_ghost);
    const double energy_after =
      energy_account.after_mesh_change(*mechanics, v, u_ghost, energy_before);
    history.transfer(RunContext());
    pcout << "  mesh at t = " << time << ": " << cells_before << " -> "
          << tria->n_global_active_cells() << " cells, " << unknowns_before
          << " -> " << dof_handler.n_dofs()
          << " unknowns; E_kin+E_el = " << std::setprecision(10)
          << energy_before << " -> " << energy_after << std::setprecision(6)
          << std::endl;
    watchdog.act(watchdog.mesh_change_warning(energy_account.balance(),
                                              energy_after - energy_before,
                                              time),
                 step,
                 pcout);
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::assemble_committed_reactions()
  {
    mechanics->assemble(ghosted(u, u_ghost),
                        ghosted(v, v_ghost),
                        a,
                        integrator.is_dynamic() ? 1. : 0.,
                        0.,
                        increment_constraints,
                        false,
                        residual,
                        jacobian,
                        residual_full_old);
  }

  template <int dim>
  void
  Simulator<dim>::reevaluate_committed_state()
  {
    assemble_committed_reactions();
    if (contact)
      {
        // the node states, forces and face memory of the committed state,
        // committed again without work
        contact->set_times(time, time);
        contact->update_candidates(u_ghost);
      }
    setup_sparsity();
    if (contact)
      {
        VectorType contact_residual(residual);
        contact->assemble(trial_state(),
                          increment_constraints,
                          false,
                          contact_residual,
                          jacobian,
                          residual_full_old);
        contact->commit_step(u_ghost, u, true);
      }
  }

#define INSTANTIATE(dim)                                        \
  template bool Simulator<dim>::adapt_mesh();                   \
  template bool Simulator<dim>::refine_and_transfer();          \
  template void Simulator<dim>::assemble_committed_reactions(); \
  template void Simulator<dim>::reevaluate_committed_state();
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
