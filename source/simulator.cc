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

    declare_contact_parameters(prm, layout, dim);

    prm.enter_subsection("Parallel");
    ParallelParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    RefinementParameters::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm,
                            std::ostream     &screen,
                            const MPI_Comm    comm)
    : pcout(screen, is_root(comm))
    , mpi_communicator(comm)
  {
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      parameters_text = text.str();
    }
    scene.parse_parameters(prm);
    layout                = scene.layout();
    layout.obstacle_names = obstacle_names(prm);
    for (const auto &name : layout.body_names)
      {
        BodyParameters body;
        body.name = name;
        prm.enter_subsection(BodyParameters::subsection_name(name));
        body.parse_parameters(prm, dim);
        prm.leave_subsection();
        bodies.push_back(body);
      }
    prm.enter_subsection("Boundary conditions");
    dirichlet.parse_parameters(prm, layout);
    prm.leave_subsection();

    prm.enter_subsection("Time integration");
    integrator.parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Nonlinear solver");
    newton.parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_parameters.parse_parameters(prm);
    prm.leave_subsection();

    contact = create_contact_formulation<dim>(prm, layout);
    if (contact)
      fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(1),
                                           dim,
                                           FE_Q<dim>(1),
                                           contact->n_extra_components());
    else
      fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim);

    prm.enter_subsection("Parallel");
    parallel_parameters.parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    refinement.parse_parameters(prm);
    prm.leave_subsection();
    // p4est refines and repartitions in parallel
    if (refinement.adapt_to_contact)
      parallel_parameters.mesh = ParallelParameters::Mesh::distributed;
    base_level = parallel_parameters.global_refinements;

    mechanics = std::make_unique<SolidMechanics<dim>>(dof_handler, bodies);
    if (parallel_parameters.mesh == ParallelParameters::Mesh::distributed)
      {
        auto distributed =
          std::make_unique<parallel::distributed::Triangulation<dim>>(
            mpi_communicator);
        // the cells at secondary surfaces carry the contact work too (the
        // weights are all a cell has: 1000 for a bulk cell)
        if (contact && parallel_parameters.contact_cell_weight > 1)
          {
            const auto ids    = contact->secondary_boundary_ids();
            const auto weight = parallel_parameters.contact_cell_weight;
            distributed->signals.weight.connect(
              [ids, weight](
                const typename Triangulation<dim>::cell_iterator &cell,
                const typename Triangulation<dim>::CellStatus) -> unsigned int {
                for (const auto &face : cell->face_iterators())
                  if (face->at_boundary() &&
                      std::find(ids.begin(), ids.end(), face->boundary_id()) !=
                        ids.end())
                    return 1000 * weight;
                return 1000;
              });
          }
        triangulation = std::move(distributed);
      }
    else
      triangulation = std::make_unique<parallel::shared::Triangulation<dim>>(
        mpi_communicator,
        Triangulation<dim>::none,
        false,
        parallel_parameters.partitioner ==
            ParallelParameters::Partitioner::metis ?
          parallel::shared::Triangulation<dim>::partition_metis :
          parallel::shared::Triangulation<dim>::partition_zorder);
    scene.create_triangulation(*triangulation);
    {
      // refuse a refinement that could not fit in memory before making it
      const double cells =
        triangulation->n_global_active_cells() *
        std::pow(2., dim * parallel_parameters.global_refinements);
      AssertThrow(cells <= 1e8,
                  ExcMessage(
                    "Parallel/Global refinements = " +
                    std::to_string(parallel_parameters.global_refinements) +
                    " would make " + std::to_string(cells) + " cells from " +
                    std::to_string(triangulation->n_global_active_cells()) +
                    ": at most 1e8 are allowed (about 100 GB). Lower it or "
                    "the Scene's Refinement factor."));
    }
    triangulation->refine_global(parallel_parameters.global_refinements);
    if (auto distributed =
          dynamic_cast<parallel::distributed::Triangulation<dim> *>(
            triangulation.get()))
      distributed->repartition();
    dof_handler.reinit(*triangulation);
    timer = std::make_unique<TimerOutput>(comm,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    newton.set_timer(*timer);
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
  Simulator<dim>::setup_system(const bool first)
  {
    TimerOutput::Scope t(*timer, "setup");
    dof_handler.distribute_dofs(*fe);
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    if (contact)
      {
        if (first)
          contact->setup(dof_handler);
        else
          contact->remesh(dof_handler);
        locally_relevant.add_indices(contact->surface_dofs());
        // the first process opens contact_history.csv (a restart continues
        // it; a reload at a checkpoint keeps it open)
        if (first && !contact_writer)
          check_collectively(mpi_communicator, [&]() {
            contact_writer =
              std::make_unique<ContactWriter<dim>>(*contact,
                                                   mpi_communicator,
                                                   output_parameters.directory,
                                                   restarting);
          });
        else
          contact_writer->locate_monitored_nodes(*contact);
      }

    {
      // the rigid-body modes of each body, for an algebraic multigrid:
      // translations and rotations about the origin (reference positions)
      const unsigned int               n_rotations = dim == 2 ? 1 : 3;
      const unsigned int               per_body    = dim + n_rotations;
      std::vector<std::vector<double>> modes(
        per_body * bodies.size(),
        std::vector<double>(locally_owned.n_elements(), 0.));
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const Point<dim>  &x     = cell->vertex(v);
              const unsigned int first = per_body * cell->material_id();
              std::array<types::global_dof_index, dim> dofs;
              for (unsigned int d = 0; d < dim; ++d)
                dofs[d] = cell->vertex_dof_index(v, d);
              if (!locally_owned.is_element(dofs[0]))
                continue;
              std::array<unsigned int, dim> local;
              for (unsigned int d = 0; d < dim; ++d)
                local[d] = locally_owned.index_within_set(dofs[d]);
              for (unsigned int d = 0; d < dim; ++d)
                modes[first + d][local[d]] = 1;
              if (dim == 2)
                {
                  modes[first + 2][local[0]] = -x[1];
                  modes[first + 2][local[1]] = x[0];
                }
              else
                for (unsigned int r = 0; r < 3; ++r)
                  {
                    // rotation about axis r: e_r x x
                    const unsigned int a = (r + 1) % 3, b = (r + 2) % 3;
                    modes[first + dim + r][local[a]] = -x[b];
                    modes[first + dim + r][local[b]] = x[a];
                  }
            }
      newton.set_near_null_space(std::move(modes), fe->n_components());
    }

    // Dirichlet degrees of freedom: Newton increments vanish there; so do
    // the multipliers the contact formulation does not use.
    increment_constraints.clear();
    IndexSet prescribed(dof_handler.n_dofs());
    for (const auto &p : dirichlet.values(dof_handler, 0.))
      prescribed.add_index(p.first);
    // a process assembles contact rows of surface nodes whose cells it
    // may not have (on a distributed mesh): it must know which are held
    if (contact)
      {
        IndexSet held = prescribed & contact->surface_dofs();
        prescribed.add_indices(union_over_processes(held, mpi_communicator));
      }
    dirichlet_dofs = prescribed;
    for (const auto i : prescribed)
      increment_constraints.add_line(i);
    if (contact)
      contact->add_constraints(increment_constraints);
    {
      std::vector<bool> displacement(fe->n_components(), false);
      for (unsigned int d = 0; d < dim; ++d)
        displacement[d] = true;
      displacement_dofs =
        DoFTools::extract_dofs(dof_handler, ComponentMask(displacement));
    }
    held_dofs = IndexSet(dof_handler.n_dofs());
    for (const auto &line : increment_constraints.get_lines())
      held_dofs.add_index(line.index);
    held_dofs.compress();
    // hanging nodes of an adapted mesh (on contact surfaces in 3-D only);
    // an unused multiplier stays held at zero
    hanging_constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    // (distribute() is collective: every process must take the same path)
    any_hanging_nodes =
      Utilities::MPI::max(unsigned(hanging_constraints.n_constraints() > 0),
                          mpi_communicator) > 0;
    for (const auto &line : hanging_constraints.get_lines())
      if (!increment_constraints.is_constrained(line.index))
        {
          increment_constraints.add_line(line.index);
          increment_constraints.add_entries(line.index, line.entries);
        }
    if (contact)
      contact->add_hanging_constraints(increment_constraints);
    increment_constraints.close();
    mechanics->setup(increment_constraints);

    for (VectorType *vec : {&u,
                            &v,
                            &a,
                            &u_new,
                            &v_new,
                            &a_new,
                            &residual,
                            &residual_full,
                            &residual_full_old,
                            &increment,
                            &body_force})
      vec->reinit(locally_owned, mpi_communicator);
    for (VectorType *vec : {&u_ghost, &v_ghost})
      vec->reinit(locally_owned, locally_relevant, mpi_communicator);
    body_force = mechanics->body_force();
    if (contact && first)
      contact->update_candidates(ghosted(u, u_ghost));
    // before the sparsity pattern: an iterative solver wants the fill-in
    // (a refused solver is refused on every process: one message)
    check_collectively(mpi_communicator, [&]() {
      linear_solver_name =
        newton.choose_linear_solver(dof_handler.n_dofs(),
                                    integrator.is_dynamic(),
                                    Utilities::MPI::n_mpi_processes(
                                      mpi_communicator));
    });
    // after a mesh change: once the candidates of the transferred state are
    // known (reevaluate_committed_state())
    if (first)
      setup_sparsity();
  }

  template <int dim>
  void
  Simulator<dim>::setup_sparsity()
  {
    // the bulk couples displacements only; contact adds its own couplings
    DynamicSparsityPattern dsp(locally_relevant);
    mechanics->make_sparsity_pattern(increment_constraints, dsp);
    if (contact)
      contact->add_sparsity(dsp);
    // rows assembled on other processes (cells and contact patches at the
    // edges of the parts) go to their owners
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned,
                                               mpi_communicator,
                                               locally_relevant);
    if (contact && newton.wants_fill_in())
      {
        // from the complete rows of this process's groups; the rows it
        // fills go to their owners as well
        const auto fill =
          MultiplierCondensation::fill_in(dsp, multiplier_groups());
        IndexSet rows(dof_handler.n_dofs());
        for (const auto &f : fill)
          rows.add_indices(f.rows.begin(), f.rows.end());
        rows.add_indices(locally_owned);
        rows.compress();
        DynamicSparsityPattern fill_pattern(dof_handler.n_dofs(),
                                            dof_handler.n_dofs(),
                                            rows);
        for (const auto &f : fill)
          for (const auto r : f.rows)
            fill_pattern.add_entries(r, f.columns.begin(), f.columns.end());
        SparsityTools::distribute_sparsity_pattern(fill_pattern,
                                                   locally_owned,
                                                   mpi_communicator,
                                                   rows);
        std::vector<types::global_dof_index> columns;
        for (const auto r : locally_owned)
          {
            columns.clear();
            for (auto it = fill_pattern.begin(r); it != fill_pattern.end(r);
                 ++it)
              columns.push_back(it->column());
            dsp.add_entries(r, columns.begin(), columns.end(), true);
          }
      }
    newton.release_factorization();
    jacobian.reinit(locally_owned, locally_owned, dsp, mpi_communicator);
    structure_changed = true;
  }

  template <int dim>
  void
  Simulator<dim>::interpolate_initial_state()
  {
    const unsigned int n_components = fe->n_components();
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
    VectorTools::interpolate_based_on_material_id(MappingQ1<dim>(),
                                                  dof_handler,
                                                  u_map,
                                                  u);
    VectorTools::interpolate_based_on_material_id(MappingQ1<dim>(),
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
    dirichlet.rates(dof_handler, 0., h, v_dirichlet, a_dirichlet);
    const auto u_dirichlet = dirichlet.values(dof_handler, 0.);
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

        // consistent initial acceleration: M a0 = f_body - C v0 - f_int(u0)
        AffineConstraints<double> acceleration_constraints;
        for (const auto &p : a_dirichlet)
          {
            acceleration_constraints.add_line(p.first);
            acceleration_constraints.set_inhomogeneity(p.first, p.second);
          }
        // multipliers have no inertia; the bodies start out of contact
        std::vector<bool> extra(fe->n_components(), true);
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
        mechanics->assemble_initial_acceleration_system(
          ghosted(u, u_ghost),
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
    // reactions at t = 0 for the trapezoidal external work
    assemble_committed_reactions();

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
    if (contact)
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
          contact->check_initial_state(screen_log());
        });
      }

    energies = EnergyBalance();
    energies.kinetic =
      integrator.is_dynamic() ? mechanics->kinetic_energy(v) : 0.;
    energies.elastic = mechanics->elastic_energy(u_ghost);
    energies.initial = energies.kinetic + energies.elastic;
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
    time                         = 0;
    step                         = 0;
    cumulative_newton_iterations = 0;
    time_step_cuts               = 0;
    rejected_steps               = 0;
    error_estimate               = 0;
    have_mean_acceleration       = false;
    dt_before                    = 0;
    dt_next                      = integrator.time_step();
    good_since_cut               = 0;
    cut_since                    = 2;
    last_checkpoint_step         = -1;
    wall_time_before             = 0;
    checkpoint_timer.restart();
    setup_system();
    apply_initial_conditions();

    open_output_files(false);

    print_problem_size();
    output_step(0, 0., true);
  }


  template <int dim>
  std::vector<std::string>
  Simulator<dim>::statistics_columns() const
  {
    std::vector<std::string> columns{"step",
                                     "time",
                                     "dt",
                                     "newton_iterations",
                                     "cumulative_newton_iterations",
                                     "kinetic_energy",
                                     "elastic_energy",
                                     "damping_dissipation",
                                     "external_work",
                                     "energy_balance_error",
                                     "wall_time",
                                     "final_residual",
                                     "time_step_cuts",
                                     "linear_iterations"};
    if (integrator.is_dissipative())
      columns.insert(columns.begin() + 8, "numerical_dissipation");
    if (contact)
      for (const auto &c : contact->statistics_columns())
        columns.push_back(c);
    if (refinement.adapt_to_contact)
      for (const auto *c :
           {"cells", "unknowns", "mesh_changes", "transfer_energy"})
        columns.emplace_back(c);
    if (integrator.error_tolerance() > 0)
      for (const auto *c : {"error_estimate", "rejected_steps"})
        columns.emplace_back(c);
    return columns;
  }

  template <int dim>
  void
  Simulator<dim>::open_output_files(const bool append)
  {
    check_collectively(mpi_communicator, [&]() {
      if (is_root(mpi_communicator))
        statistics =
          std::make_unique<StatisticsFile>(output_parameters.directory +
                                             "/statistics.csv",
                                           statistics_columns(),
                                           append);
    });
    solution_writer =
      std::make_unique<SolutionWriter<dim>>(mpi_communicator,
                                            output_parameters.directory,
                                            contact ?
                                              contact->extra_component_names() :
                                              std::vector<std::string>());
  }

  template <int dim>
  void
  Simulator<dim>::print_problem_size()
  {
    pcout << "Scene '" << scene.name()
          << "': " << triangulation->n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " unknowns, " << bodies.size() << " bod"
          << (bodies.size() == 1 ? "y" : "ies") << "; linear solver "
          << linear_solver_name << std::endl;
    if (balances_between_steps())
      pcout << "Time integration " << integrator.scheme_name()
            << ": alpha_m = " << integrator.alpha_m()
            << ", alpha_f = " << integrator.alpha_f()
            << ", beta = " << integrator.beta()
            << ", gamma = " << integrator.gamma() << std::endl;
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    if (n_processes > 1)
      {
        const auto cells =
          Utilities::MPI::gather(mpi_communicator,
                                 triangulation->n_locally_owned_active_cells());
        const auto unknowns =
          Utilities::MPI::gather(mpi_communicator, locally_owned.n_elements());
        const auto nodes =
          Utilities::MPI::gather(mpi_communicator,
                                 contact ? contact->n_owned_contact_nodes() :
                                           0u);
        pcout << n_processes << " MPI processes ("
              << (parallel_parameters.mesh ==
                      ParallelParameters::Mesh::distributed ?
                    std::string("distributed mesh") :
                    parallel_parameters.partitioner_name() + " partition")
              << "); cells / unknowns / secondary contact nodes:";
        for (unsigned int p = 0; p < cells.size(); ++p)
          pcout << (p ? ", " : " ") << cells[p] << " / " << unknowns[p] << " / "
                << nodes[p];
        pcout << std::endl;
      }
  }

  template <int dim>
  void
  Simulator<dim>::set_trial_velocity_and_acceleration()
  {
    const double dt = dt_current;
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
  Simulator<dim>::local_error_estimate()
  {
    // The change of the acceleration over the step, a_{n+1} - a_n, from
    // the mean accelerations of this step and the one before, so that the
    // step-to-step alternation of the trapezoidal rule's acceleration after
    // a velocity jump (undamped, at the step's Nyquist frequency, not a
    // motion a smaller step resolves) does not count; the same for a
    // smooth motion. The first step uses a_{n+1} - a_n; a mesh change
    // transfers the last mean acceleration.
    const double dt = dt_current;
    mean_acceleration.reinit(v);
    for (const auto i : locally_owned)
      mean_acceleration(i) = (v_new(i) - v(i)) / dt;
    mean_acceleration.compress(VectorOperation::insert);
    const bool history =
      have_mean_acceleration && mean_acceleration_before.size() == v.size();
    // the mean acceleration (1 - gamma) a_n + gamma a_{n+1} belongs to
    // t_n + gamma dt_n (to first order): the two are that far apart
    const double gamma   = integrator.gamma();
    const double scale   = dt / (gamma * dt + (1 - gamma) * dt_before);
    const double factor  = std::abs(integrator.local_error_factor(dt));
    double       largest = 0;
    for (const auto i : displacement_dofs)
      if (!increment_constraints.is_constrained(i))
        {
          const double change =
            history ?
              (mean_acceleration(i) - mean_acceleration_before(i)) * scale :
              a_new(i) - a(i);
          largest = std::max(largest, factor * std::abs(change));
        }
    return Utilities::MPI::max(largest, mpi_communicator);
  }

  template <int dim>
  double
  Simulator<dim>::apply_velocity_update()
  {
    const double work =
      integrator.is_dynamic() ? contact->velocity_update_request() : 0.;
    const VectorType *force = contact->velocity_update_force();
    if (work == 0 || force == nullptr)
      return 0;
    TimerOutput::Scope t(*timer, "velocity update");

    // the bodies the step's contact impulse acted on: only their free
    // velocities change
    std::vector<double>                  touched(bodies.size(), 0.);
    std::vector<types::global_dof_index> cell_dofs(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto i : cell_dofs)
            if (locally_owned.is_element(i) && (*force)(i) != 0)
              touched[cell->material_id()] = 1;
        }
    Utilities::MPI::sum(touched, mpi_communicator, touched);

    // A projection onto the energy the step should end with (after Hairer,
    // Lubich and Wanner, Geometric Numerical Integration, IV.4: along the
    // gradient of the kinetic energy, M^-1 M v = v): a factor 1 + s on the
    // free velocities of those bodies. It can remove all of their kinetic
    // energy; D^-1 M v (lumped metric) and the least-norm M_FF^-1 (M v)_F
    // were tried and could not (doc/contact.md)
    VectorType direction(v_new);
    for (const auto i : locally_owned)
      if (is_held(i))
        direction(i) = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && touched[cell->material_id()] == 0.)
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto i : cell_dofs)
            if (locally_owned.is_element(i))
              direction(i) = 0;
        }
    direction.compress(VectorOperation::insert);

    // K(v + s w) = K(v) + s b + s^2 K(w) = K(v) - work: the root of
    // smaller size, or the largest removal (s = -1 when the prescribed
    // velocities do not couple) if the step created more than w carries
    const double k_w = mechanics->kinetic_energy(direction);
    if (!(k_w > 0))
      return 0;
    VectorType sum(v_new);
    sum += direction;
    const double k_v          = mechanics->kinetic_energy(v_new);
    const double b            = mechanics->kinetic_energy(sum) - k_v - k_w;
    const double discriminant = b * b - 4 * k_w * work;
    double       s            = -b / (2 * k_w);
    if (discriminant >= 0)
      {
        const double root = std::sqrt(discriminant);
        const double s1 = (-b + root) / (2 * k_w), s2 = (-b - root) / (2 * k_w);
        s = std::abs(s1) < std::abs(s2) ? s1 : s2;
      }
    v_new.add(s, direction);
    const double change = k_w * s * s + b * s;
    contact->add_velocity_update_work(change);
    return change;
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
                        integrator.effective_acceleration_factor(dt_current),
                        integrator.velocity_factor(dt_current),
                        increment_constraints,
                        with_jacobian,
                        residual_out,
                        jacobian_out,
                        residual_full);
    t.stop();
    if (contact)
      {
        TimerOutput::Scope tc(*timer, "contact assembly");
        contact->assemble(TrialState{u_ghost,
                                     v_ghost,
                                     integrator.velocity_factor(dt_current),
                                     dt_current,
                                     integrator.is_dynamic(),
                                     integrator},
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
    dt_current = dt;
    u_new      = trial;
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
    if (dt != dt_current)
      structure_changed = true;
    dt_current         = dt;
    const double t_new = time + dt;

    {
      auto un = u_new.begin();
      auto uo = u.begin();
      auto vo = v.begin();
      auto ao = a.begin();
      for (; un != u_new.end(); ++un, ++uo, ++vo, ++ao)
        *un = integrator.predict(dt, *uo, *vo, *ao);
      if (contact)
        for (const auto i : contact->multiplier_dofs())
          if (locally_owned.is_element(i))
            u_new(i) = u(i);
      u_new.compress(VectorOperation::insert);
      set_prescribed_values(u_new, t_new);
    }

    if (contact)
      {
        contact->set_times(time, t_new);
        contact->start_step();
      }
    NewtonSolver::Result result;
    // of the passes before, on the meshes before
    unsigned int earlier_iterations = 0, earlier_linear_iterations = 0;
    bool         adapted = false;
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
            !adaptation_due(step + 1,
                            contact ? contact->n_active_nodes() : 0,
                            committed_active_nodes) ||
            !adapt_mesh())
          break;
        adapted           = true;
        structure_changed = true;
        set_prescribed_values(u_new, t_new);
        if (contact)
          {
            contact->set_times(time, t_new);
            contact->start_step();
          }
      }
    std::string failure = result.failure;

    EnergyBalance updated = energies;
    // the bulk's energy account and the contact work before the step, for
    // the numerical dissipation
    const double bulk_before = energies.kinetic + energies.elastic +
                               energies.dissipated - energies.external;
    const double contact_work_before = contact ? contact->contact_work() : 0.;
    if (result.converged)
      {
        TimerOutput::Scope t(*timer, "energies");
        set_trial_velocity_and_acceleration();
        if (balances_between_steps())
          {
            // residual_full holds the balance between the steps (of the
            // last assembly, whose effective acceleration is still set);
            // the reactions and the next step need M a_{n+1} + F_{n+1}
            residual_full.add(-integrator.old_force_factor(), force_old);
            VectorType inertia(residual_full);
            increment = a_new;
            increment -= effective_acceleration;
            mechanics->inertia_force(increment, 1., inertia);
            residual_full += inertia;
          }
        VectorType mean_velocity(v);
        mean_velocity.sadd(0.5, 0.5, v_new);
        increment = u_new;
        increment -= u;
        updated.dissipated +=
          dt * mechanics->damping_product(mean_velocity, mean_velocity);
        double boundary_work = 0;
        for (const auto &line : increment_constraints.get_lines())
          if (locally_owned.is_element(line.index) && is_held(line.index))
            boundary_work +=
              increment(line.index) * 0.5 *
              (residual_full_old(line.index) + residual_full(line.index));
        updated.external +=
          Utilities::MPI::sum(boundary_work, mpi_communicator) +
          increment * body_force;
        updated.kinetic =
          integrator.is_dynamic() ? mechanics->kinetic_energy(v_new) : 0.;
        updated.elastic = mechanics->elastic_energy(u_ghost);
        if (!std::isfinite(updated.error()))
          {
            std::vector<std::string> which;
            for (const auto &e :
                 {std::make_pair(updated.kinetic, "kinetic"),
                  std::make_pair(updated.elastic, "elastic"),
                  std::make_pair(updated.dissipated, "damping dissipation"),
                  std::make_pair(updated.external, "external work")})
              if (!std::isfinite(e.first))
                which.push_back(
                  std::string(e.first != e.first ? "NaN " : "infinite ") +
                  e.second);
            failure = "the energies are not finite numbers (" +
                      join(which, ", ") + "; the largest nodal body force is " +
                      format_number(body_force.linfty_norm()) + ")";
          }
        // DataOut evaluates the stresses at the corners (collective: on
        // every process, whatever the failure)
        const std::string inverted = inverted_corner();
        if (failure.empty())
          failure = inverted;
        // e.g. a node that went through a surface unnoticed
        if (failure.empty() && contact)
          failure = contact->check_step(u_ghost);
      }
    // adaptive time steps: the step is solved again with a smaller dt if
    // its local error is too large (not below the minimum dt)
    rejected_by_estimate = false;
    if (failure.empty() && result.converged && integrator.error_tolerance() > 0)
      {
        const double tolerance = integrator.error_tolerance();
        error_estimate         = local_error_estimate();
        step_factor =
          error_estimate > 0 ?
            std::clamp(0.9 * std::cbrt(tolerance / error_estimate), 0.2, 2.) :
            2.;
        if (error_estimate > tolerance &&
            dt > integrator.minimum_time_step() * (1 + 1e-9))
          {
            rejected_by_estimate = true;
            failure              = "the local error estimate " +
                      format_number(error_estimate) +
                      " exceeds Time integration/Error tolerance = " +
                      format_number(tolerance);
          }
      }
    if (!failure.empty() || !result.converged)
      {
        structure_changed = true;
        last_failure      = failure.empty() ? "no convergence" : failure;
        if (adapted)
          last_failure += " (on the mesh adapted to the step)";
        pcout << "  step to t = " << t_new << " with dt = " << dt
              << " failed: " << last_failure << std::endl;
        return false;
      }

    energies = updated;
    if (contact)
      {
        // u_ghost: the converged state, as the last assembly saw it
        contact->commit_step(u_ghost, u);
        previous_active_nodes  = committed_active_nodes;
        committed_active_nodes = contact->n_active_nodes();
        energies.kinetic += apply_velocity_update();
        energies.frictional = contact->dissipated_energy();
        energies.obstacle   = contact->obstacle_work();
      }
    // what the bulk lost beyond its physical account (damping, external
    // work, the work of the contact forces), all trapezoidal in time
    if (integrator.is_dissipative())
      energies.numerical +=
        (contact ? contact->contact_work() - contact_work_before : 0.) -
        (energies.kinetic + energies.elastic + energies.dissipated -
         energies.external - bulk_before);
    if (integrator.error_tolerance() > 0)
      {
        mean_acceleration_before.swap(mean_acceleration);
        dt_before              = dt;
        have_mean_acceleration = true;
      }
    u.swap(u_new);
    v.swap(v_new);
    a.swap(a_new);
    residual_full_old.swap(residual_full);
    time = t_new;
    ++step;
    structure_changed = false;
    cumulative_newton_iterations += result.iterations;
    linear_iterations = result.linear_iterations;
    output_step(result.iterations, result.final_residual, false);
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::output_step(const unsigned int newton_iterations,
                              const double       final_residual,
                              const bool         force_vtu)
  {
    TimerOutput::Scope  t(*timer, "output");
    std::vector<double> row{double(step),
                            time,
                            step == 0 ? 0. : dt_current,
                            double(newton_iterations),
                            double(cumulative_newton_iterations),
                            energies.kinetic,
                            energies.elastic,
                            energies.dissipated,
                            energies.external,
                            energies.error(),
                            wall_time_before + wall_timer.wall_time(),
                            final_residual,
                            double(time_step_cuts),
                            double(step == 0 ? 0 : linear_iterations)};
    if (integrator.is_dissipative())
      row.insert(row.begin() + 8, energies.numerical);
    if (contact)
      for (const double x : contact->statistics())
        row.push_back(x);
    if (refinement.adapt_to_contact)
      for (const double x : {double(triangulation->n_global_active_cells()),
                             double(dof_handler.n_dofs()),
                             double(mesh_changes),
                             energies.transfer})
        row.push_back(x);
    if (integrator.error_tolerance() > 0)
      for (const double x :
           {step == 0 ? 0. : error_estimate, double(rejected_steps)})
        row.push_back(x);
    const unsigned int interval = output_parameters.vtu_interval;
    try
      {
        // a failed write (a full disk) stops every process, naming the file
        check_collectively(mpi_communicator, [&]() {
          if (statistics)
            statistics->write_row(row);
          if (contact && step > 0)
            contact_writer->write_history(*contact, time);
        });
        if (interval > 0 && (force_vtu || step % interval == 0))
          write_solution();
      }
    catch (const ExcCollective &e)
      {
        AssertThrow(false,
                    ExcCollective(
                      exception_message(e) + " The run stops at step " +
                      std::to_string(step) + ", t = " + format_number(time) +
                      "; what was written before is complete."));
      }

    if (step > 0)
      pcout << "Step " << std::setw(5) << step << "  t = " << std::setw(10)
            << std::setprecision(6) << time << "  dt = " << std::setw(9)
            << dt_current << "  Newton " << std::setw(2) << newton_iterations
            << "  |R| = " << std::scientific << std::setprecision(2)
            << final_residual
            << "  E_kin+E_el = " << energies.kinetic + energies.elastic
            << "  balance error = " << energies.error() << std::defaultfloat
            << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::set_prescribed_values(VectorType &x, const double t)
  {
    for (const auto &p : dirichlet.values(dof_handler, t))
      if (locally_owned.is_element(p.first))
        x(p.first) = p.second;
    x.compress(VectorOperation::insert);
    if (any_hanging_nodes)
      hanging_constraints.distribute(x);
  }

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
                                refinement.lookahead_steps * dt_current) :
          std::vector<Point<dim>>();
      const unsigned int dropped = mark_cells_near_contact(dof_handler,
                                                           u_ghost,
                                                           zone,
                                                           refinement,
                                                           base_level);
      if (dropped > 0 && !cell_limit_reported)
        pcout << "  Mesh refinement/Maximum cells = "
              << refinement.maximum_cells << " reached at t = " << time << ": "
              << dropped
              << " cells near the contact are not refined (reported once)"
              << std::endl;
      cell_limit_reported = cell_limit_reported || dropped > 0;
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

    const double energy_before = energies.kinetic + energies.elastic;
    // the velocity that coarsening would interpolate: its projection keeps
    // the momenta and cannot add kinetic energy (the multipliers and the
    // prescribed values stay)
    {
      std::vector<bool> extra(fe->n_components(), true);
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
    std::vector<VectorType *> state{&u, &v, &a, &u_new};
    const bool                keep_history =
      integrator.error_tolerance() > 0 && have_mean_acceleration;
    if (keep_history)
      state.push_back(&mean_acceleration_before);
    std::vector<VectorType>         old(state.size());
    std::vector<const VectorType *> old_pointers;
    for (unsigned int i = 0; i < state.size(); ++i)
      old_pointers.push_back(&ghosted(*state[i], old[i]));
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    transfer.prepare_for_coarsening_and_refinement(old_pointers);
    tria->execute_coarsening_and_refinement();
    t.stop();

    setup_system(false);
    transfer.interpolate(state);
    for (VectorType *x : state)
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
    set_prescribed_values(u_new, time + dt_current);
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

    energies.kinetic =
      integrator.is_dynamic() ? mechanics->kinetic_energy(v) : 0.;
    energies.elastic          = mechanics->elastic_energy(ghosted(u, u_ghost));
    const double energy_after = energies.kinetic + energies.elastic;
    energies.transfer += energy_after - energy_before;
    ++mesh_changes;
    have_mean_acceleration = keep_history;
    pcout << "  mesh at t = " << time << ": " << cells_before << " -> "
          << tria->n_global_active_cells() << " cells, " << unknowns_before
          << " -> " << dof_handler.n_dofs()
          << " unknowns; E_kin+E_el = " << std::setprecision(10)
          << energy_before << " -> " << energy_after << std::setprecision(6)
          << std::endl;
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
        contact->assemble(TrialState{u_ghost,
                                     v_ghost,
                                     integrator.velocity_factor(dt_current),
                                     dt_current,
                                     integrator.is_dynamic(),
                                     integrator},
                          increment_constraints,
                          false,
                          contact_residual,
                          jacobian,
                          residual_full_old);
        contact->commit_step(u_ghost, u);
      }
  }

  template <int dim>
  Tensor<1, dim>
  Simulator<dim>::reaction_force(const std::string &surface) const
  {
    const types::boundary_id id = layout.surface_id(surface);
    Tensor<1, dim>           force;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<bool> mask(fe->n_components(), false);
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
  Simulator<dim>::write_solution()
  {
    std::vector<std::pair<const VectorType *, std::string>> fields;
    std::vector<VectorType>                                 field_ghosts;
    if (contact)
      {
        fields = contact->nodal_output_fields();
        field_ghosts.resize(fields.size());
        for (unsigned int f = 0; f < fields.size(); ++f)
          fields[f].first = &ghosted(*fields[f].first, field_ghosts[f]);
      }
    const VectorType &u_out = ghosted(u, scratch_ghost[0]);
    const VectorType &v_out = ghosted(v, scratch_ghost[1]);
    check_collectively(mpi_communicator, [&]() {
      solution_writer
        ->write(dof_handler, *mechanics, u_out, v_out, time, step, fields);
      if (contact)
        contact_writer->write_surfaces(*contact, step);
    });
    // only once every process has written its piece
    check_collectively(mpi_communicator, [&]() {
      solution_writer->write_records(time, step);
    });
    last_vtu_step = step;
  }

  template <int dim>
  std::string
  Simulator<dim>::inverted_corner() const
  {
    // corners of the trial state's neo-Hookean cells (the trapezoidal
    // rule's points)
    double     smallest = std::numeric_limits<double>::max();
    Point<dim> where;
    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim>                    fe_values(*fe,
                            QTrapezoid<dim>(),
                            update_gradients | update_quadrature_points);
    std::vector<Tensor<2, dim>>      gradients(fe_values.n_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !mechanics->material(cell->material_id()).is_linear())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(u_ghost, gradients);
          for (unsigned int q = 0; q < gradients.size(); ++q)
            {
              const double J =
                determinant(unit_symmetric_tensor<dim>() + gradients[q]);
              if (!(J >= smallest))
                {
                  smallest = J;
                  where    = fe_values.quadrature_point(q);
                }
            }
        }
    // the same answer on every process: the smallest over all
    const auto all =
      Utilities::MPI::all_gather(mpi_communicator,
                                 std::make_pair(smallest, where));
    for (const auto &p : all)
      if (!(p.first >= smallest))
        {
          smallest = p.first;
          where    = p.second;
        }
    if (smallest > 0)
      return "";
    std::ostringstream message;
    message << "Inverted element: det F = " << smallest
            << " <= 0 at the corner (reference position " << where
            << ") of a neo-Hookean element";
    return message.str();
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
  Simulator<dim>::run(const std::string &checkpoint)
  {
    if (checkpoint.empty())
      initialize();
    else
      restart(checkpoint);
    const double time_step         = integrator.time_step();
    const double end_time          = integrator.end_time();
    const double minimum_time_step = integrator.minimum_time_step();
    double      &dt                = dt_next;
    while (time < end_time - 1e-9 * time_step)
      {
        // SIGINT, SIGTERM: stop between steps, with complete outputs and a
        // checkpoint to continue from
        if (const int signal = stop_signal(mpi_communicator))
          {
            if (last_checkpoint_step != int(step))
              write_checkpoint();
            stop_run(signal == SIGINT  ? "Interrupted (SIGINT)." :
                     signal == SIGTERM ? "Terminated (SIGTERM)." :
                                         "Stopped by a signal.",
                     signal,
                     " A checkpoint of this step is in '" +
                       Checkpoints::directory(output_parameters.directory,
                                              step) +
                       "': 'contact-dynamics --restart " +
                       output_parameters.directory + "' continues the run.");
          }
        const double dt_try = std::min(dt, end_time - time);
        if (advance(dt_try))
          {
            // the mesh for the next step (without solving this one again;
            // `step` is the one just completed)
            if (refinement.adapt_to_contact &&
                refinement.passes_per_step == 0 &&
                adaptation_due(step,
                               committed_active_nodes,
                               previous_active_nodes))
              adapt_mesh();
            if (integrator.error_tolerance() > 0)
              {
                // after a Newton failure, two good steps before it grows
                const bool recently_cut = cut_since < 2;
                cut_since += recently_cut;
                dt = std::clamp(dt_try * (recently_cut ?
                                            std::min(step_factor, 1.) :
                                            step_factor),
                                minimum_time_step,
                                time_step);
                if (error_estimate > integrator.error_tolerance())
                  pcout << "  accepted at the Minimum time step with the "
                           "error estimate "
                        << error_estimate << " above the tolerance"
                        << std::endl;
              }
            else if (dt < time_step && ++good_since_cut >= 2)
              {
                dt             = std::min(2 * dt, time_step);
                good_since_cut = 0;
              }
            const unsigned int interval = output_parameters.checkpoint_interval;
            const double       minutes = output_parameters.checkpoint_wall_time;
            // (the wall time of the first process decides for all)
            if ((interval > 0 && step % interval == 0) ||
                (minutes > 0 &&
                 Utilities::MPI::broadcast(mpi_communicator,
                                           checkpoint_timer.wall_time(),
                                           0) >= 60 * minutes))
              write_checkpoint();
          }
        else if (rejected_by_estimate)
          {
            ++rejected_steps;
            dt = std::max(dt_try * step_factor, minimum_time_step);
            pcout << "  reducing the time step to " << dt << std::endl;
          }
        else
          {
            ++time_step_cuts;
            good_since_cut = 0;
            cut_since      = 0;
            dt             = dt_try / 2;
            if (dt < minimum_time_step)
              stop_run("The time step would have to be cut to " +
                       format_number(dt) + " at t = " + format_number(time) +
                       ", below Time integration/Minimum time step = " +
                       format_number(minimum_time_step) +
                       " (the last attempt: " + last_failure + ").");
            pcout << "  cutting the time step to " << dt << std::endl;
          }
      }
    if (output_parameters.vtu_interval > 0 && last_vtu_step != int(step))
      write_solution();

    pcout << "Finished at t = " << time << " after " << step << " steps ("
          << cumulative_newton_iterations << " Newton iterations, "
          << time_step_cuts << " time step cuts"
          << (integrator.error_tolerance() > 0 ?
                ", " + std::to_string(rejected_steps) +
                  " steps rejected by the error estimate" :
                std::string())
          << "). Results are in '" << output_parameters.directory << "'."
          << std::endl;
    timer->print_summary();
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace ContactDynamics
