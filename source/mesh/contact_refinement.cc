#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/rtree.h>

#include <contact_dynamics/contact/quadratic_face.h>
#include <contact_dynamics/mesh/contact_refinement.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ContactDynamics
{
  void
  RefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    const RefinementParameters d;
    prm.declare_entry(
      "Adapt to contact",
      default_text(d.adapt_to_contact),
      Patterns::Bool(),
      "Refine the mesh where contact is active or predicted and coarsen "
      "where it has left, transferring the state (displacement, velocity, "
      "acceleration, multipliers) to the new mesh; the energy change of "
      "each transfer is its own column of statistics.csv. The mesh is then "
      "distributed (p4est) whatever Parallel/Mesh says. In 3-D the refined "
      "contact surfaces have hanging nodes, whose multipliers follow their "
      "neighbours' (doc/refinement.md). See doc/refinement.md for what it costs and buys.");
    prm.declare_entry("Interval",
                      default_text(d.interval),
                      Patterns::Integer(1, 1000000),
                      "Adapt the mesh after every this many time steps.");
    prm.declare_entry("On contact change",
                      default_text(d.on_contact_change),
                      Patterns::Bool(),
                      "Also adapt after a step (between the Intervals) in "
                      "which the number of active contact nodes changed.");
    prm.declare_entry(
      "Maximum levels",
      default_text(d.maximum_levels),
      Patterns::Integer(0, 12),
      "Refinement levels above the initial mesh (each halves the cell "
      "size); coarsening never goes below the initial mesh.");
    prm.declare_entry("Maximum cells",
                      default_text(d.maximum_cells),
                      Patterns::Integer(1, 100000000),
                      "Refinements that would make more cells than this are "
                      "not made (those farthest from the contact first).");
    prm.declare_entry(
      "Buffer cells",
      default_text(d.buffer_cells),
      Patterns::Double(0.1, 100),
      "A cell within this many cell diameters of the contact zone is "
      "refined: each level keeps about this many cells between the "
      "contact and the next coarser level. A cell farther than this many "
      "plus one of its parent's diameters is coarsened. The diameter is "
      "that of the contact zone's cells at the cell's level (or the "
      "cell's own, if smaller): the large far cells of a graded mesh do "
      "not count their own size.");
    prm.declare_entry(
      "Lookahead steps",
      default_text(d.lookahead_steps),
      Patterns::Double(0, 1e6),
      "The contact zone: the secondary nodes in contact and those whose "
      "gap, at its present rate, closes within this many time steps.");
    prm.declare_entry(
      "Passes per step",
      default_text(d.passes_per_step),
      Patterns::Integer(0, 20),
      "After a step converged, the mesh is adapted to its contact zone and "
      "the step solved again on the new mesh, until the mesh no longer "
      "changes or this many times (each pass refines by one level at "
      "most: a quasi-static step wants Maximum levels passes). 0: the mesh "
      "is adapted after the step for the next one, and no step is solved "
      "twice (the Lookahead steps must then see the contact coming).");
    prm.declare_entry("Coarsen",
                      default_text(d.coarsen),
                      Patterns::Bool(),
                      "Coarsen where the contact has left (interpolation: "
                      "the energy change is reported).");
  }

  void
  RefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    adapt_to_contact  = prm.get_bool("Adapt to contact");
    interval          = prm.get_integer("Interval");
    on_contact_change = prm.get_bool("On contact change");
    maximum_levels    = prm.get_integer("Maximum levels");
    maximum_cells     = prm.get_integer("Maximum cells");
    buffer_cells      = prm.get_double("Buffer cells");
    lookahead_steps   = prm.get_double("Lookahead steps");
    passes_per_step   = prm.get_integer("Passes per step");
    coarsen           = prm.get_bool("Coarsen");
  }

  namespace
  {
    /** An owned cell with its distance to the contact zone and diameter. */
    template <int dim>
    struct MeasuredCell
    {
      typename Triangulation<dim>::active_cell_iterator cell;
      double                                            distance, diameter;
    };

    /**
     * The distance of each owned cell's current position to the contact
     * zone (its flags cleared), and `zone_diameter`: the largest diameter a
     * cell touching the contact zone would have at the top level (cells
     * are never above it), the unit of the buffer, so that a graded mesh's
     * large far cells do not reach the zone by their own size.
     */
    template <int dim>
    std::vector<MeasuredCell<dim>>
    measure_cells(const DoFHandler<dim, dim>    &dof_handler,
                  const VectorType              &u,
                  const std::vector<Point<dim>> &contact_points,
                  const unsigned int             top,
                  double                        &zone_diameter)
    {
      const auto                     tree = pack_rtree(contact_points);
      const unsigned int             kids = 1u << dim;
      std::vector<MeasuredCell<dim>> measured;
      zone_diameter = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          cell->clear_refine_flag();
          cell->clear_coarsen_flag();
          Point<dim>                       center;
          std::array<Point<dim>, 1 << dim> x;
          for (const unsigned int v : cell->vertex_indices())
            {
              x[v] = cell->vertex(v);
              for (unsigned int d = 0; d < dim; ++d)
                x[v][d] += u(cell->vertex_dof_index(v, d));
              center += x[v] / double(kids);
            }
          double radius = 0;
          for (const auto &p : x)
            radius = std::max(radius, center.distance(p));
          double distance = std::numeric_limits<double>::infinity();
          if (!contact_points.empty())
            {
              std::vector<Point<dim>> nearest;
              tree.query(boost::geometry::index::nearest(center, 1),
                         std::back_inserter(nearest));
              distance = std::max(0., center.distance(nearest[0]) - radius);
            }
          const double diameter = 2 * radius;
          if (distance == 0)
            zone_diameter = std::max(
              zone_diameter,
              std::ldexp(diameter,
                         int(cell->level()) -
                           int(std::max<unsigned int>(top, cell->level()))));
          measured.push_back(
            {typename Triangulation<dim>::active_cell_iterator(cell),
             distance,
             diameter});
        }
      return measured;
    }

    /**
     * Flags the cells to refine among `refine` (relative distance, cell)
     * within the cell limit: the nearest cells only (a bisection on the
     * relative distance, the same on every process). The number of cells
     * of all processes left unflagged.
     */
    template <int dim>
    unsigned int
    flag_within_limit(
      const std::vector<
        std::pair<double, typename Triangulation<dim>::active_cell_iterator>>
                                 &refine,
      const Triangulation<dim>   &tria,
      const RefinementParameters &parameters,
      const MPI_Comm              comm)
    {
      const unsigned int kids     = 1u << dim;
      const double       buffer   = parameters.buffer_cells;
      const double       n_cells  = tria.n_global_active_cells();
      const auto         n_refine = [&](const double threshold) {
        double n = 0;
        for (const auto &r : refine)
          n += r.first <= threshold;
        return Utilities::MPI::sum(n, comm);
      };
      const double room =
        (double(parameters.maximum_cells) - n_cells) / (kids - 1);
      double threshold = buffer;
      if (n_refine(threshold) > room)
        {
          double low = -1, high = buffer;
          for (unsigned int i = 0; i < 50; ++i)
            {
              const double mid                    = 0.5 * (low + high);
              (n_refine(mid) > room ? high : low) = mid;
            }
          threshold = low;
        }
      unsigned int dropped = 0;
      for (const auto &r : refine)
        if (r.first <= threshold)
          r.second->set_refine_flag();
        else
          ++dropped;
      return Utilities::MPI::sum(dropped, comm);
    }
  } // namespace

  template <int dim>
  unsigned int
  mark_cells_near_contact(const DoFHandler<dim, dim>    &dof_handler,
                          const VectorType              &u,
                          const std::vector<Point<dim>> &contact_points,
                          const RefinementParameters    &parameters,
                          const unsigned int             base_level)
  {
    const MPI_Comm     comm   = dof_handler.get_communicator();
    const auto        &tria   = dof_handler.get_triangulation();
    const double       buffer = parameters.buffer_cells;
    const unsigned int top    = base_level + parameters.maximum_levels;

    // distance of each owned cell's current position to the contact zone
    double     zone_diameter = 0;
    const auto measured =
      measure_cells(dof_handler, u, contact_points, top, zone_diameter);
    zone_diameter = Utilities::MPI::max(zone_diameter, comm);

    std::vector<
      std::pair<double, typename Triangulation<dim>::active_cell_iterator>>
      refine;
    for (const auto &m : measured)
      {
        const unsigned int level = m.cell->level();
        // the diameter a contact-zone cell has at this cell's level
        const double unit =
          zone_diameter > 0 ?
            std::min(m.diameter,
                     std::ldexp(zone_diameter,
                                int(std::max<unsigned int>(top, level)) -
                                  int(level))) :
            m.diameter;
        if (m.distance < buffer * unit && level < top)
          refine.emplace_back(m.distance / unit, m.cell);
        else if (parameters.coarsen && level > base_level &&
                 m.distance > (buffer + 1) * 2 * unit)
          m.cell->set_coarsen_flag();
      }

    // the cell limit: refine the nearest cells only
    return flag_within_limit<dim>(refine, tria, parameters, comm);
  }

  namespace
  {
    // y <- C^T y for the constraints' owned lines with entries (their rows
    // go to the rows they follow), then the constrained rows are zero
    void
    condense(const AffineConstraints<double> &constraints, VectorType &y)
    {
      const IndexSet owned = y.locally_owned_elements();
      VectorType     moved(y);
      for (const auto &line : constraints.get_lines())
        if (owned.is_element(line.index))
          for (const auto &entry : line.entries)
            moved.add(std::vector<types::global_dof_index>{entry.first},
                      std::vector<double>{entry.second * y(line.index)});
      moved.compress(VectorOperation::add);
      y = moved;
      constraints.set_zero(y);
    }
  } // namespace

  void
  condense_rows(const AffineConstraints<double> &constraints, VectorType &y)
  {
    condense(constraints, y);
  }

  void
  solve_constrained_mass_system(const TrilinosWrappers::SparseMatrix &mass,
                                const AffineConstraints<double> &constraints,
                                VectorType                      &x)
  {
    // CG, Jacobi-preconditioned: the mass matrix is conditioned
    // independently of the mesh size
    const IndexSet owned = x.locally_owned_elements();
    VectorType     diagonal(x), r(x), p(x), q(x), z(x), y(x);
    for (const auto i : owned)
      diagonal(i) =
        constraints.is_constrained(i) || !(mass.diag_element(i) > 0) ?
          0. :
          1. / mass.diag_element(i);
    diagonal.compress(VectorOperation::insert);
    // rows without mass (multipliers) take no part
    r = x;
    constraints.set_zero(r);
    for (const auto i : owned)
      if (diagonal(i) == 0)
        r(i) = 0;
    r.compress(VectorOperation::insert);
    x                   = 0;
    const double b_norm = r.l2_norm();
    unsigned int it     = 0;
    if (b_norm > 0)
      {
        z = r;
        z.scale(diagonal);
        p          = z;
        double rho = r * z;
        for (; it < 10000 && r.l2_norm() > 1e-14 * b_norm; ++it)
          {
            y = p;
            constraints.distribute(y);
            mass.vmult(q, y);
            condense(constraints, q);
            const double alpha = rho / (p * q);
            x.add(alpha, p);
            r.add(-alpha, q);
            z = r;
            z.scale(diagonal);
            const double rho_new = r * z;
            p.sadd(rho_new / rho, 1., z);
            rho = rho_new;
          }
        // (the norms are global: every process throws, with one message)
        AssertThrow(r.l2_norm() <= 1e-12 * b_norm,
                    ExcCollective("The mass solve of a mesh transfer did not "
                                  "converge (relative residual " +
                                  std::to_string(r.l2_norm() / b_norm) +
                                  " after " + std::to_string(it) +
                                  " CG iterations)."));
      }
    constraints.distribute(x);
  }

  namespace
  {
    /** Degree 1: the children's other vertices, d-linearly. */
    template <typename Cell>
    void
    add_linear_family(const Cell                &cell,
                      const IndexSet            &fixed,
                      AffineConstraints<double> &family)
    {
      constexpr int dim = Cell::AccessorType::dimension;
      const auto   &fe  = cell->get_fe();
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        for (const unsigned int k : cell->child(c)->vertex_indices())
          {
            if (k == c)
              continue; // the parent's vertex
            Point<dim> xi;
            for (unsigned int d = 0; d < dim; ++d)
              xi[d] = 0.5 * (GeometryInfo<dim>::unit_cell_vertex(c)[d] +
                             GeometryInfo<dim>::unit_cell_vertex(k)[d]);
            for (unsigned int comp = 0; comp < fe.n_components(); ++comp)
              {
                const auto i = cell->child(c)->vertex_dof_index(k, comp);
                if (family.is_constrained(i) || fixed.is_element(i))
                  continue;
                family.add_line(i);
                for (const unsigned int p : cell->vertex_indices())
                  if (const double w =
                        GeometryInfo<dim>::d_linear_shape_function(xi, p);
                      std::abs(w) > 1e-14)
                    family.add_entry(i, cell->vertex_dof_index(p, comp), w);
              }
          }
    }

    /**
     * Degree 2: the parent's 3^dim nodes are vertices of the children
     * (coordinates 0, 1/2, 1 in the parent); the children's other nodes
     * (at 1/4 and 3/4) follow them by the parent's quadratic functions.
     */
    template <typename Cell>
    void
    add_quadratic_family(const Cell                &cell,
                         const IndexSet            &fixed,
                         AffineConstraints<double> &family)
    {
      constexpr int dim         = Cell::AccessorType::dimension;
      const auto   &fe          = cell->get_fe();
      const auto   &support     = fe.base_element(0).get_unit_support_points();
      const auto    parent_node = [](const double t) {
        return std::abs(t - std::round(2 * t) / 2) < 1e-12;
      };
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (unsigned int c = 0; c < cell->n_children(); ++c)
        {
          const auto child = cell->child(c);
          child->get_dof_indices(dofs);
          for (unsigned int b = 0; b < support.size(); ++b)
            {
              Point<dim> xi;
              bool       at_parent_node = true;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  xi[d] = 0.5 * (GeometryInfo<dim>::unit_cell_vertex(c)[d] +
                                 support[b][d]);
                  at_parent_node = at_parent_node && parent_node(xi[d]);
                }
              if (at_parent_node)
                continue;
              std::array<std::array<double, 3>, dim> L;
              for (unsigned int d = 0; d < dim; ++d)
                L[d] = QuadraticFace::lagrange(xi[d]);
              for (unsigned int comp = 0; comp < fe.n_components(); ++comp)
                {
                  const auto i = dofs[fe.component_to_system_index(comp, b)];
                  if (family.is_constrained(i) || fixed.is_element(i))
                    continue;
                  family.add_line(i);
                  // parent node n: per direction 0, 1/2 or 1 (n_d = 0, 1,
                  // 2), a vertex of the child on its lower side
                  for (unsigned int n = 0; n < Utilities::pow(3u, dim); ++n)
                    {
                      double       w           = 1;
                      unsigned int child_index = 0, vertex = 0;
                      for (unsigned int d = 0, m = n; d < dim; ++d, m /= 3)
                        {
                          // (lagrange() orders its nodes 0, 1, 1/2)
                          w *= L[d][(2 * (m % 3)) % 3];
                          child_index |= (m % 3 == 2) << d;
                          vertex |= (m % 3 != 0) << d;
                        }
                      if (std::abs(w) > 1e-14)
                        family.add_entry(i,
                                         cell->child(child_index)
                                           ->vertex_dof_index(vertex, comp),
                                         w);
                    }
                }
            }
        }
    }
  } // namespace

  template <int dim>
  bool
  project_before_coarsening(const DoFHandler<dim, dim>           &dof_handler,
                            const TrilinosWrappers::SparseMatrix &mass,
                            const AffineConstraints<double>      &hanging,
                            const IndexSet                       &fixed,
                            VectorType                           &v)
  {
    const MPI_Comm comm  = dof_handler.get_communicator();
    const auto    &fe    = dof_handler.get_fe();
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    // the removed nodes of the families to be coarsened follow the
    // parent's nodes (interpolation of the element's degree in the parent)
    AffineConstraints<double> family(relevant);
    unsigned int              n_families = 0;
    for (const auto &cell : dof_handler.cell_iterators())
      {
        bool coarsened = cell->has_children();
        for (unsigned int c = 0; coarsened && c < cell->n_children(); ++c)
          coarsened = cell->child(c)->is_active() &&
                      cell->child(c)->is_locally_owned() &&
                      cell->child(c)->coarsen_flag_set();
        if (!coarsened)
          continue;
        ++n_families;
        if (fe.degree == 1)
          add_linear_family(cell, fixed, family);
        else
          add_quadratic_family(cell, fixed, family);
      }
    if (Utilities::MPI::sum(n_families, comm) == 0)
      return false;
    for (const auto &line : hanging.get_lines())
      if (relevant.is_element(line.index) &&
          !family.is_constrained(line.index) && !fixed.is_element(line.index))
        {
          family.add_line(line.index);
          family.add_entries(line.index, line.entries);
        }
    family.make_consistent_in_parallel(owned, relevant, comm);
    // H: also the fixed values (homogeneous: the unknown is w - w0)
    AffineConstraints<double> with_fixed(relevant);
    for (const auto &line : family.get_lines())
      {
        with_fixed.add_line(line.index);
        with_fixed.add_entries(line.index, line.entries);
      }
    for (const auto i : fixed &relevant)
      if (!with_fixed.is_constrained(i))
        with_fixed.add_line(i);
    family.close();
    with_fixed.close();

    // w0: the fixed values and what follows from them alone
    VectorType w0(v);
    for (const auto i : owned)
      if (!fixed.is_element(i))
        w0(i) = 0;
    w0.compress(VectorOperation::insert);
    family.distribute(w0);

    // H^T M H z = H^T M (v - w0)
    VectorType r(v);
    r -= w0;
    VectorType solution(v);
    mass.vmult(solution, r);
    condense(with_fixed, solution);
    solve_constrained_mass_system(mass, with_fixed, solution);
    v = w0;
    v += solution;
    return true;
  }

  template <int dim>
  bool
  any_cell_flagged(const Triangulation<dim> &triangulation, const MPI_Comm comm)
  {
    unsigned int flagged = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (cell->refine_flag_set() || cell->coarsen_flag_set()))
        ++flagged;
    return Utilities::MPI::sum(flagged, comm) > 0;
  }

  template unsigned int
  mark_cells_near_contact<2>(const DoFHandler<2, 2> &,
                             const VectorType &,
                             const std::vector<Point<2>> &,
                             const RefinementParameters &,
                             const unsigned int);
  template unsigned int
  mark_cells_near_contact<3>(const DoFHandler<3, 3> &,
                             const VectorType &,
                             const std::vector<Point<3>> &,
                             const RefinementParameters &,
                             const unsigned int);
  template bool
  project_before_coarsening<2>(const DoFHandler<2, 2> &,
                               const TrilinosWrappers::SparseMatrix &,
                               const AffineConstraints<double> &,
                               const IndexSet &,
                               VectorType &);
  template bool
  project_before_coarsening<3>(const DoFHandler<3, 3> &,
                               const TrilinosWrappers::SparseMatrix &,
                               const AffineConstraints<double> &,
                               const IndexSet &,
                               VectorType &);
  template bool
  any_cell_flagged<2>(const Triangulation<2> &, const MPI_Comm);
  template bool
  any_cell_flagged<3>(const Triangulation<3> &, const MPI_Comm);
} // namespace ContactDynamics
