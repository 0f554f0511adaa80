// The Simulator's initial state: the bodies' initial conditions, checked
// for finite inputs, and the consistent initial acceleration.
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
  void
  Simulator<dim>::interpolate_initial_state()
  {
    const unsigned int n_components = discretization.fe().n_components();
    std::vector<std::unique_ptr<FunctionParser<dim>>>   functions;
    std::map<types::material_id, const Function<dim> *> u_map, v_map;
    // muparser reads an expression at its first evaluation: evaluate each
    // once on every process here, since a process without cells of the body
    // would not, and would wait for the others in the interpolation
    check_collectively(mpi_communicator, [&]() {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        for (const bool displacement : {true, false})
          {
            const std::string parameter =
              BodyParameters::subsection_name(bodies[b].name) +
              (displacement ? "/Initial displacement" : "/Initial velocity");
            auto expressions =
              split_vector_expression(displacement ?
                                        bodies[b].initial_displacement :
                                        bodies[b].initial_velocity,
                                      dim,
                                      parameter);
            expressions.resize(n_components, "0");
            auto f = std::make_unique<FunctionParser<dim>>(n_components);
            try
              {
                f->initialize(FunctionParser<dim>::default_variable_names(),
                              expressions,
                              {{"pi", numbers::PI}});
              }
            catch (...)
              {
                AssertThrow(false,
                            ExcMessage("FunctionParser cannot read the "
                                       "parameter '" +
                                       parameter + "'."));
              }
            try
              {
                for (unsigned int c = 0; c < dim; ++c)
                  f->value(Point<dim>(), c);
              }
            catch (...)
              {
                AssertThrow(false,
                            ExcMessage(
                              parameter + " = " +
                              (displacement ? bodies[b].initial_displacement :
                                              bodies[b].initial_velocity) +
                              ": the expression cannot be evaluated (it may "
                              "use the variables x, y" +
                              (dim == 3 ? ", z" : "") +
                              ", t and the constant pi)."));
              }
            (displacement ? u_map : v_map)[b] = f.get();
            functions.push_back(std::move(f));
          }
    });
    VectorTools::interpolate_based_on_material_id(discretization.mapping(),
                                                  dof_handler,
                                                  u_map,
                                                  u);
    VectorTools::interpolate_based_on_material_id(discretization.mapping(),
                                                  dof_handler,
                                                  v_map,
                                                  v);
  }

  template <int dim>
  void
  Simulator<dim>::check_initial_inputs(
    const std::map<types::global_dof_index, double> &u_dirichlet,
    const std::map<types::global_dof_index, double> &v_dirichlet,
    const std::map<types::global_dof_index, double> &a_dirichlet,
    const double                                     h) const
  {
    // name the input that is not finite, not what it leads to
    std::vector<std::string> causes;
    for (const auto &body : bodies)
      for (const double f : body.body_force)
        if (!std::isfinite(f))
          causes.push_back(BodyParameters::subsection_name(body.name) +
                           "/Body force");
    // residual norms must not overflow either
    if (!std::isfinite(body_force.l2_norm()))
      {
        std::vector<std::string> forces;
        for (const auto &body : bodies)
          {
            std::vector<std::string> f;
            for (const double x : body.body_force)
              f.push_back(format_number(x));
            forces.push_back(BodyParameters::subsection_name(body.name) +
                             "/Body force = " + join(f, ", "));
          }
        causes.push_back("the nodal body forces are too large for the "
                         "residual norms (" +
                         join(forces, "; ") + ")");
      }
    // the initial conditions of every body: which one is not finite
    // where is not known here
    const auto initial = [&](const bool displacement) {
      std::vector<std::string> entries;
      for (const auto &body : bodies)
        entries.push_back(
          BodyParameters::subsection_name(body.name) +
          (displacement ?
             "/Initial displacement = " + body.initial_displacement :
             "/Initial velocity = " + body.initial_velocity));
      return std::string(displacement ? "an initial displacement" :
                                        "an initial velocity") +
             " not finite somewhere (" + join(entries, "; ") + ")";
    };
    if (!std::isfinite(u.linfty_norm()))
      causes.emplace_back(initial(true));
    if (!std::isfinite(v.linfty_norm()))
      causes.emplace_back(initial(false));
    const auto finite = [](const std::map<types::global_dof_index, double> &m) {
      for (const auto &p : m)
        if (!std::isfinite(p.second))
          return false;
      return true;
    };
    if (!finite(u_dirichlet))
      causes.emplace_back("Boundary conditions/Dirichlet (a value at t = 0 "
                          "is not finite)");
    if (!finite(v_dirichlet) || !finite(a_dirichlet))
      {
        // the rates are central differences over h = 1e-4 time steps
        if (!std::isnormal(h * h))
          causes.push_back("Time integration/Time step = " +
                           format_number(integrator.time_step()) +
                           " (too small to difference the Dirichlet values "
                           "over 1e-4 of it: (1e-4 dt)^2 underflows)");
        else
          causes.emplace_back(
            "Boundary conditions/Dirichlet (the velocity or acceleration "
            "of a prescribed motion at t = 0 is not finite: the expression "
            "is not smooth there)");
      }
    const std::vector<std::string> all =
      Utilities::MPI::n_mpi_processes(mpi_communicator) > 1 ?
        Utilities::MPI::all_gather(mpi_communicator, join(causes, "; ")) :
        std::vector<std::string>{join(causes, "; ")};
    for (const auto &c : all)
      AssertThrow(c.empty(),
                  ExcCollective("The initial state cannot be computed: " + c +
                                "."));
  }

  template <int dim>
  void
  Simulator<dim>::apply_initial_conditions()
  {
    TimerOutput::Scope t(*timer, "initial conditions");
    interpolate_initial_state();
    a = 0;

    // The prescribed motion wins at Dirichlet degrees of freedom; its rate
    // by central differences keeps the Newmark update of those dofs
    // consistent from the first step on.
    std::map<types::global_dof_index, double> v_dirichlet, a_dirichlet;
    const double                              h = 1e-4 * integrator.time_step();
    dirichlet.rates(discretization.mapping(),
                    dof_handler,
                    0.,
                    h,
                    v_dirichlet,
                    a_dirichlet);
    const auto u_dirichlet =
      dirichlet.values(discretization.mapping(), dof_handler, 0.);
    check_initial_inputs(u_dirichlet, v_dirichlet, a_dirichlet, h);
    for (const auto &p : u_dirichlet)
      if (locally_owned.is_element(p.first))
        u(p.first) = p.second;
    u.compress(VectorOperation::insert);
    if (!integrator.is_dynamic())
      v = 0;
    else
      {
        for (const auto &p : v_dirichlet)
          if (locally_owned.is_element(p.first))
            v(p.first) = p.second;
        v.compress(VectorOperation::insert);

        solve_initial_acceleration(a_dirichlet);
      }
    // reactions at t = 0 for the trapezoidal external work
    assemble_committed_reactions();

    check_initial_state();
    if (contact)
      check_initial_contact();

    energy_account.start(*mechanics, v, u_ghost);
  }

  template <int dim>
  void
  Simulator<dim>::initialize()
  {
    wall_timer.restart();
    check_collectively(mpi_communicator, [&]() {
      if (is_root(mpi_communicator))
        {
          create_output_directory(output_parameters.directory);
          // a new run: checkpoints of an earlier one here would continue
          // that run against this run's files
          Checkpoints::remove_all_checkpoints(output_parameters.directory);
        }
    });
    time = 0;
    step = 0;
    controller.start();
    last_checkpoint_step = -1;
    wall_time_before     = 0;
    checkpoint_timer.restart();
    setup_system();
    apply_initial_conditions();

    open_output_files(false);

    print_problem_size();
    output_step(0, 0., true);
  }


  template <int dim>
  void
  Simulator<dim>::solve_initial_acceleration(
    const std::map<types::global_dof_index, double> &a_dirichlet)
  {
    // consistent initial acceleration: M a0 = f_body - C v0 - f_int(u0)
    AffineConstraints<double> acceleration_constraints;
    for (const auto &p : a_dirichlet)
      {
        acceleration_constraints.add_line(p.first);
        acceleration_constraints.set_inhomogeneity(p.first, p.second);
      }
    // multipliers have no inertia; the bodies start out of contact
    std::vector<bool> extra(discretization.fe().n_components(), true);
    for (unsigned int d = 0; d < dim; ++d)
      extra[d] = false;
    for (const auto i :
         union_over_processes(DoFTools::extract_dofs(dof_handler,
                                                     ComponentMask(extra)),
                              mpi_communicator))
      if (!acceleration_constraints.is_constrained(i))
        acceleration_constraints.add_line(i);
    acceleration_constraints.close();
    MatrixType mass;
    mass.reinit(jacobian);
    mechanics->assemble_initial_acceleration_system(ghosted(u, u_ghost),
                                                    ghosted(v, v_ghost),
                                                    acceleration_constraints,
                                                    mass,
                                                    residual);
    // M is symmetric positive definite and, scaled by its diagonal,
    // conditioned independently of the mesh size: CG converges in a
    // few tens of iterations and divides with the processes, where a
    // direct solve of the gathered matrix took 7.9 s at 298k unknowns
    // (CG failures are collective: every process takes the fallback)
    // (1e-14 is 5 to 15 times the round-off floor measured up to 321k
    // unknowns; should CG still fail, the direct solve follows)
    const double rhs_norm = residual.l2_norm();
    if (rhs_norm > 0)
      try
        {
          SolverControl control(10000, 1e-14 * rhs_norm, false, false);
          TrilinosWrappers::SolverCG           cg(control);
          TrilinosWrappers::PreconditionJacobi jacobi;
          jacobi.initialize(mass);
          cg.solve(mass, a, residual, jacobi);
        }
      catch (const std::exception &)
        {
          SolverControl                  control(1, 0, false, false);
          TrilinosWrappers::SolverDirect solver(control);
          solver.solve(mass, a, residual);
        }
    acceleration_constraints.distribute(a);
  }

  template <int dim>
  void
  Simulator<dim>::check_initial_state() const
  {
    // the inputs were finite (check_initial_inputs): what is not finite
    // now overflowed (linfty: the l2 norm of 1e200 overflows)
    std::vector<std::string> infinite;
    if (!std::isfinite(u.linfty_norm()))
      infinite.emplace_back("displacement");
    if (!std::isfinite(v.linfty_norm()))
      infinite.emplace_back("velocity");
    if (!std::isfinite(a.linfty_norm()))
      infinite.emplace_back("acceleration");
    if (!std::isfinite(residual_full_old.linfty_norm()))
      infinite.emplace_back("internal forces");
    AssertThrow(infinite.empty(),
                ExcCollective(
                  "The initial " + join(infinite, ", ") +
                  " are not finite numbers although every input is: a "
                  "value overflows (body force " +
                  format_number(body_force.linfty_norm()) +
                  " per node, Young's moduli, densities, initial "
                  "displacement and velocity, Dirichlet values at t = 0, "
                  "Time integration/Time step = " +
                  format_number(integrator.time_step()) +
                  "), or a body is neither held nor free."));
  }

  template <int dim>
  void
  Simulator<dim>::check_initial_contact()
  {
    // gaps at the initial state: overlapping bodies stop the run here
    contact->set_times(time, time);
    if (contact->update_candidates(u_ghost))
      setup_sparsity();
    VectorType contact_residual(residual), contact_full(residual_full_old);
    contact->assemble(TrialState{u_ghost,
                                 v_ghost,
                                 0.,
                                 integrator.time_step(),
                                 integrator.is_dynamic(),
                                 integrator},
                      increment_constraints,
                      false,
                      contact_residual,
                      jacobian,
                      contact_full);
    check_collectively(mpi_communicator, [&]() {
      contact->check_initial_state(u_ghost, screen_log());
    });
  }

#define INSTANTIATE(dim)                                          \
  template void Simulator<dim>::interpolate_initial_state();      \
  template void Simulator<dim>::check_initial_inputs(             \
    const std::map<types::global_dof_index, double> &u_dirichlet, \
    const std::map<types::global_dof_index, double> &v_dirichlet, \
    const std::map<types::global_dof_index, double> &a_dirichlet, \
    const double                                     h) const;                                        \
  template void Simulator<dim>::apply_initial_conditions();       \
  template void Simulator<dim>::initialize();                     \
  template void Simulator<dim>::solve_initial_acceleration(       \
    const std::map<types::global_dof_index, double> &);           \
  template void Simulator<dim>::check_initial_state() const;      \
  template void Simulator<dim>::check_initial_contact();
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
