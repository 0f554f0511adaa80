// The Simulator's setup: parameters read into its parts, the mesh, the
// degrees of freedom with their constraints, and the sparsity pattern.
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
  Simulator<dim>::Simulator(ParameterHandler &prm,
                            std::ostream     &screen,
                            const MPI_Comm    comm)
    : pcout(screen, is_root(comm))
    , adaptation(refinement,
                 [this]() {
                   return contact ? contact->n_active_nodes() : 0;
                 })
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

    prm.enter_subsection("Energy watchdog");
    watchdog.parse_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Finite element");
    discretization.parse_parameters(prm);
    prm.leave_subsection();
    contact = create_contact_formulation<dim>(prm, layout);
    discretization.create(contact ? contact->n_extra_components() : 0);

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

    mechanics = std::make_unique<SolidMechanics<dim>>(discretization.mapping(),
                                                      dof_handler,
                                                      bodies);
    create_mesh();
    dof_handler.reinit(*triangulation);
    history.add(state);
    history.add(controller);
    history.add(energy_account);
    history.add(adaptation);
    timer = std::make_unique<TimerOutput>(comm,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    newton.set_timer(*timer);
  }

  template <int dim>
  void
  Simulator<dim>::setup_system(const bool first, const bool sparsity)
  {
    TimerOutput::Scope t(*timer, "setup");
    dof_handler.distribute_dofs(discretization.fe());
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    if (contact)
      {
        if (first)
          contact->setup(dof_handler, discretization.mapping());
        else
          contact->remesh(dof_handler, discretization.mapping());
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

    set_near_null_space();

    setup_constraints();

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
                                      mpi_communicator),
                                    dim);
    });
    // after a mesh change: once the candidates of the transferred state are
    // known (reevaluate_committed_state())
    if (first && sparsity)
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
            fill_pattern.add_entries(r,
                                     f.columns.begin(),
                                     f.columns.end(),
                                     true);
        SparsityTools::distribute_sparsity_pattern(fill_pattern,
                                                   locally_owned,
                                                   mpi_communicator,
                                                   rows);
        // (row_length() and column_number() find a row in O(log n);
        // begin(r) of a row with no entries walks on to the next stored
        // row, O(n): quadratic setup, 217 s of 224 at 298k unknowns, issue
        // 40)
        std::vector<types::global_dof_index> columns;
        for (const auto r : locally_owned)
          {
            columns.resize(fill_pattern.row_length(r));
            if (columns.empty())
              continue;
            for (unsigned int k = 0; k < columns.size(); ++k)
              columns[k] = fill_pattern.column_number(r, k);
            dsp.add_entries(r, columns.begin(), columns.end(), true);
          }
      }
    newton.release_factorization();
    jacobian.reinit(locally_owned, locally_owned, dsp, mpi_communicator);
    structure_changed = true;
  }

  template <int dim>
  void
  Simulator<dim>::create_mesh()
  {
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
    discretization.set_geometry(scene.cell_geometry());
    {
      // refuse a refinement that could not fit in memory before making it
      // (a cell of degree p holds about p^dim times the nodes)
      const double cells =
        triangulation->n_global_active_cells() *
        std::pow(2., dim * parallel_parameters.global_refinements);
      const double allowed = 1e8 / std::pow(discretization.degree(), dim);
      AssertThrow(cells <= allowed,
                  ExcMessage(
                    "Parallel/Global refinements = " +
                    std::to_string(parallel_parameters.global_refinements) +
                    " would make " + std::to_string(cells) + " cells from " +
                    std::to_string(triangulation->n_global_active_cells()) +
                    ": at most " + default_text(allowed) +
                    " are allowed with Finite element/Polynomial degree = " +
                    std::to_string(discretization.degree()) +
                    " (about 100 GB). Lower it or the Scene's Refinement "
                    "factor."));
    }
    triangulation->refine_global(parallel_parameters.global_refinements);
    if (auto distributed =
          dynamic_cast<parallel::distributed::Triangulation<dim> *>(
            triangulation.get()))
      distributed->repartition();
  }

  template <int dim>
  void
  Simulator<dim>::set_near_null_space()
  {
    // the rigid-body modes of each body, for an algebraic multigrid:
    // translations and rotations about the origin (reference positions)
    const unsigned int               n_rotations = dim == 2 ? 1 : 3;
    const unsigned int               per_body    = dim + n_rotations;
    std::vector<std::vector<double>> modes(
      per_body * bodies.size(),
      std::vector<double>(locally_owned.n_elements(), 0.));
    // at the support points of the displacement's scalar element (on the
    // cells as the mapping curves them)
    const FiniteElement<dim>            &fe   = discretization.fe();
    const FiniteElement<dim>            &base = fe.base_element(0);
    FEValues<dim>                        fe_values(discretization.mapping(),
                            base,
                            Quadrature<dim>(base.get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < base.n_dofs_per_cell(); ++i)
            {
              const Point<dim>  &x     = fe_values.quadrature_point(i);
              const unsigned int first = per_body * cell->material_id();
              std::array<types::global_dof_index, dim> dofs;
              for (unsigned int d = 0; d < dim; ++d)
                dofs[d] = cell_dofs[fe.component_to_system_index(d, i)];
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
        }
    newton.set_near_null_space(std::move(modes),
                               discretization.fe().n_components());
  }

  template <int dim>
  void
  Simulator<dim>::setup_constraints()
  {
    // Dirichlet degrees of freedom: Newton increments vanish there; so do
    // the multipliers the contact formulation does not use.
    increment_constraints.clear();
    IndexSet prescribed(dof_handler.n_dofs());
    for (const auto &p :
         dirichlet.values(discretization.mapping(), dof_handler, 0.))
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
      std::vector<bool> displacement(discretization.fe().n_components(), false);
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
  }

#define INSTANTIATE(dim)                                              \
  template Simulator<dim>::Simulator(ParameterHandler &prm,           \
                                     std::ostream     &screen,        \
                                     const MPI_Comm    comm);            \
  template void Simulator<dim>::setup_system(const bool, const bool); \
  template void Simulator<dim>::setup_sparsity();                     \
  template void Simulator<dim>::create_mesh();                        \
  template void Simulator<dim>::set_near_null_space();                \
  template void Simulator<dim>::setup_constraints();
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
