#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <deal.II/dofs/dof_tools.h>

#include <contact_dynamics/contact/contact_search.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/mortar_geometry.h>

#include <algorithm>
#include <iomanip>

namespace ContactDynamics
{
  using AD = Sacado::Fad::DFad<double>;
  using MortarGeometry::Vec;

  void
  MortarParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("c_n",
                      "1e6",
                      Patterns::Double(1e-300),
                      "Complementarity constant c_n > 0 in C_j = lambda_j - "
                      "max(0, lambda_j - c_n g_j). It changes the Newton "
                      "path, not the solution; pick it within a few orders "
                      "of magnitude of E / h (normalized) or E / h^2.");
    prm.declare_entry("Normalize c_n",
                      "true",
                      Patterns::Bool(),
                      "Divide the weighted gap by the nodal weight "
                      "integral(N_j) over the covered segments, so that c_n "
                      "does not depend on the mesh size (units stress / "
                      "length).");
    prm.declare_entry("Stabilization",
                      "persistency",
                      Patterns::Selection("none|persistency"),
                      "'persistency': a node in contact at the end of the "
                      "previous step (normalized weighted gap <= Capture "
                      "tolerance) enforces the weighted gap velocity "
                      "(Newmark-discretized) instead of the gap, so the "
                      "penetration does not change and no energy is created "
                      "('stabilized' mortar of the paper). 'none': the gap "
                      "is enforced at every step ('static' mortar).");
    prm.declare_entry("Capture tolerance",
                      "1e-5",
                      Patterns::Double(0),
                      "A node whose normalized weighted gap (length units) is "
                      "at most this value at the end of a step counts as in "
                      "contact for the persistency condition of the next "
                      "step (>= 0).");
    prm.declare_entry("Jacobian",
                      "exact",
                      Patterns::Selection("exact|approximate"),
                      "'exact': automatic differentiation through nodal "
                      "normals, projections and segment end points. "
                      "'approximate': those geometric derivatives are "
                      "dropped, as in the paper's code (more Newton "
                      "iterations).");
    prm.declare_entry("Segment quadrature points",
                      "2",
                      Patterns::Integer(1, 10),
                      "Gauss points per mortar segment, in [1, 10]; 2 "
                      "integrates the products of linear functions exactly.");
  }

  void
  MortarParameters::parse_parameters(ParameterHandler &prm)
  {
    c_n               = prm.get_double("c_n");
    normalize_c_n     = prm.get_bool("Normalize c_n");
    persistency       = prm.get("Stabilization") == "persistency";
    capture_tolerance = prm.get_double("Capture tolerance");
    exact_jacobian    = prm.get("Jacobian") == "exact";
    quadrature_points = prm.get_integer("Segment quadrature points");
  }



  template <int dim>
  MortarContact<dim>::MortarContact(const ContactParameters &contact,
                                    const MortarParameters  &mortar)
    : contact(contact)
    , mortar(mortar)
  {
    AssertThrow(dim == 2,
                ExcMessage("Mortar contact is implemented in 2-D only; set "
                           "Dimension = 2 or Contact/Formulation = none."));
  }

  template <int dim>
  std::vector<std::string>
  MortarContact<dim>::extra_component_names() const
  {
    std::vector<std::string> names{"contact_pressure", "tangential_traction"};
    names.resize(dim, "tangential_traction_2");
    return names;
  }

  template <int dim>
  void
  MortarContact<dim>::set_output_directory(const std::string &dir)
  {
    directory = dir;
  }

  template <int dim>
  void
  MortarContact<dim>::setup(const DoFHandler<dim> &dof_handler)
  {
    pairs.clear();
    pairs.resize(contact.pairs.size());
    normal_multiplier_dofs.clear();
    std::set<types::global_dof_index> secondary_normal;
    for (unsigned int p = 0; p < contact.pairs.size(); ++p)
      {
        auto &pair = pairs[p];
        pair.secondary.build(dof_handler, contact.pairs[p].secondary, 2 * dim);
        pair.primary.build(dof_handler, contact.pairs[p].primary, dim);
        AssertThrow(pair.secondary.n_faces() > 0 && pair.primary.n_faces() > 0,
                    ExcMessage("The contact pair '" + contact.pairs[p].name +
                               "' has an empty surface."));
        pair.nodes.assign(pair.secondary.n_nodes(), NodeState());
        for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
          secondary_normal.insert(pair.secondary.dofs[j][dim]);
      }
    normal_multiplier_dofs.assign(secondary_normal.begin(),
                                  secondary_normal.end());

    // every other multiplier unknown is held at zero (frictionless)
    other_multiplier_dofs.clear();
    std::vector<bool> mask(2 * dim, false);
    for (unsigned int c = dim; c < 2 * dim; ++c)
      mask[c] = true;
    const IndexSet multipliers =
      DoFTools::extract_dofs(dof_handler, ComponentMask(mask));
    for (const auto i : multipliers)
      if (secondary_normal.count(i) == 0)
        other_multiplier_dofs.push_back(i);

    // monitored points: the nearest secondary node of any pair
    monitored.clear();
    for (const auto &point : contact.monitored_points)
      {
        double                              best = 1e300;
        std::pair<unsigned int, unsigned int> where{0, 0};
        for (unsigned int p = 0; p < pairs.size(); ++p)
          for (unsigned int j = 0; j < pairs[p].secondary.n_nodes(); ++j)
            {
              double d = 0;
              for (unsigned int k = 0; k < 2; ++k)
                d += std::pow(pairs[p].secondary.reference[j][k] - point[k], 2);
              if (d < best)
                {
                  best  = d;
                  where = {p, j};
                }
            }
        monitored.push_back(where);
      }
    if (!directory.empty())
      {
        history = std::make_unique<std::ofstream>(directory +
                                                  "/contact_history.csv");
        *history << "time";
        for (const auto &m : monitored)
          {
            const Point<dim> &X = pairs[m.first].secondary.reference[m.second];
            *history << ",pressure(" << X[0] << " " << X[1] << ")"
                     << ",gap(" << X[0] << " " << X[1] << ")";
          }
        *history << std::endl;
      }
    have_state         = false;
    contact_work       = 0;
    active_set_changed = true;
  }

  template <int dim>
  void
  MortarContact<dim>::add_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto i : other_multiplier_dofs)
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
  }

  template <int dim>
  std::vector<std::vector<unsigned int>>
  MortarContact<dim>::compute_candidates(const PairData   &pair,
                                         const VectorType &u,
                                         const double      margin_factor) const
  {
    const auto boxes = [&](const ContactSurface<dim> &surface) {
      std::vector<BoundingBox<dim>> result;
      for (const auto &face : surface.faces)
        {
          const Point<dim> a = surface.position(face[0], u);
          const Point<dim> b = surface.position(face[1], u);
          BoundingBox<dim> box(std::make_pair(a, a));
          box.merge_with(BoundingBox<dim>(std::make_pair(b, b)));
          box.extend(margin_factor * a.distance(b));
          result.push_back(box);
        }
      return result;
    };
    return find_candidate_pairs(boxes(pair.secondary), boxes(pair.primary));
  }

  template <int dim>
  bool
  MortarContact<dim>::update_candidates(const VectorType &u)
  {
    if (gap_field.size() != u.size())
      {
        gap_field.reinit(u);
        gap_field = 0;
      }
    bool rebuild = false;
    for (auto &pair : pairs)
      {
        pair.candidates = compute_candidates(pair, u, 0.5);
        bool covered = !pair.pattern.empty();
        for (unsigned int e = 0; covered && e < pair.candidates.size(); ++e)
          covered = std::includes(pair.pattern[e].begin(),
                                  pair.pattern[e].end(),
                                  pair.candidates[e].begin(),
                                  pair.candidates[e].end());
        if (!covered)
          {
            // a generous margin so that the pattern lasts several steps
            pair.pattern = compute_candidates(pair, u, 2.0);
            rebuild      = true;
          }
      }
    return rebuild;
  }

  template <int dim>
  std::vector<types::global_dof_index>
  MortarContact<dim>::face_unknowns(
    const PairData                  &pair,
    const unsigned int               face,
    const std::vector<unsigned int> &primary_faces) const
  {
    const auto &s = pair.secondary;
    const auto &f = s.faces[face];
    std::vector<unsigned int> secondary_nodes;
    const unsigned int        before = s.neighbour(f[0], face);
    const unsigned int        after  = s.neighbour(f[1], face);
    if (before != ContactSurface<dim>::invalid)
      secondary_nodes.push_back(before);
    secondary_nodes.push_back(f[0]);
    secondary_nodes.push_back(f[1]);
    if (after != ContactSurface<dim>::invalid)
      secondary_nodes.push_back(after);

    std::vector<types::global_dof_index> unknowns;
    for (const unsigned int n : secondary_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(s.dofs[n][d]);
    std::set<unsigned int> primary_nodes;
    for (const unsigned int pf : primary_faces)
      for (const unsigned int n : pair.primary.faces[pf])
        primary_nodes.insert(n);
    for (const unsigned int n : primary_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        unknowns.push_back(pair.primary.dofs[n][d]);
    unknowns.push_back(s.dofs[f[0]][dim]);
    unknowns.push_back(s.dofs[f[1]][dim]);
    return unknowns;
  }

  template <int dim>
  void
  MortarContact<dim>::add_sparsity(DynamicSparsityPattern &dsp) const
  {
    for (const auto &pair : pairs)
      {
        // a node's complementarity row couples to both of its faces
        std::vector<std::set<types::global_dof_index>> node_columns(
          pair.secondary.n_nodes());
        for (unsigned int e = 0; e < pair.secondary.n_faces(); ++e)
          {
            const auto unknowns = face_unknowns(pair, e, pair.pattern[e]);
            for (const auto row : unknowns)
              for (const auto col : unknowns)
                dsp.add(row, col);
            for (const unsigned int n : pair.secondary.faces[e])
              node_columns[n].insert(unknowns.begin(), unknowns.end());
          }
        for (unsigned int j = 0; j < pair.secondary.n_nodes(); ++j)
          for (const auto col : node_columns[j])
            dsp.add(pair.secondary.dofs[j][dim], col);
      }
  }

  namespace
  {
    // An AD number that carries only the value: drops derivatives for the
    // approximate Jacobian.
    AD
    constant(const AD &x)
    {
      return AD(x.val());
    }

    Vec<AD>
    constant(const Vec<AD> &x)
    {
      Vec<AD> c;
      for (unsigned int d = 0; d < 2; ++d)
        c[d] = constant(x[d]);
      return c;
    }

    Vec<double>
    value(const Vec<AD> &x)
    {
      return Vec<double>({x[0].val(), x[1].val()});
    }

    void
    add_linearized(LinearizedValue                            &target,
                   const AD                                   &x,
                   const std::vector<types::global_dof_index> &unknowns)
    {
      target.value += x.val();
      for (unsigned int k = 0; k < unknowns.size() && k < unsigned(x.size());
           ++k)
        if (x.dx(k) != 0)
          target.derivatives[unknowns[k]] += x.dx(k);
    }

    // Adds a residual row and its derivatives, skipping constrained rows
    // and columns (all constraints are homogeneous).
    void
    add_row(const types::global_dof_index               row,
            const AD                                   &value,
            const std::vector<types::global_dof_index> &unknowns,
            const AffineConstraints<double>            &constraints,
            const bool                                  with_jacobian,
            VectorType                                 &residual,
            MatrixType                                 &jacobian)
    {
      if (constraints.is_constrained(row))
        return;
      residual(row) += value.val();
      if (with_jacobian)
        for (unsigned int k = 0; k < unknowns.size() && k < unsigned(value.size());
             ++k)
          if (value.dx(k) != 0 && !constraints.is_constrained(unknowns[k]))
            jacobian.add(row, unknowns[k], value.dx(k));
    }
  } // namespace

  template <int dim>
  void
  MortarContact<dim>::assemble_face(PairData                        &pair,
                                    const unsigned int               e,
                                    const TrialState                &state,
                                    const AffineConstraints<double> &constraints,
                                    const bool                       with_jacobian,
                                    VectorType                      &residual,
                                    MatrixType                      &jacobian,
                                    VectorType &residual_full)
  {
    const auto &s        = pair.secondary;
    const auto &p        = pair.primary;
    const auto &face     = s.faces[e];
    const auto  unknowns = face_unknowns(pair, e, pair.candidates[e]);
    const unsigned int n = unknowns.size();
    const bool         exact = mortar.exact_jacobian;

    // independent variables: positions and multipliers
    unsigned int k         = 0;
    const auto   position = [&](const Point<dim> &X) {
      Vec<AD> x;
      for (unsigned int d = 0; d < 2; ++d, ++k)
        x[d] = AD(n, k, X[d] + state.u(unknowns[k]));
      return x;
    };
    const auto velocity = [&](const Vec<AD> &x, const unsigned int first) {
      Vec<AD> v;
      for (unsigned int d = 0; d < 2; ++d)
        {
          v[d]       = state.c_v * x[d];
          v[d].val() = state.v(unknowns[first + d]);
        }
      return v;
    };

    std::map<unsigned int, Vec<AD>> xs, vs; // secondary patch nodes
    const unsigned int before = s.neighbour(face[0], e);
    const unsigned int after  = s.neighbour(face[1], e);
    for (const unsigned int node : {before, face[0], face[1], after})
      if (node != ContactSurface<dim>::invalid)
        {
          const unsigned int first = k;
          xs[node]                 = position(s.reference[node]);
          vs[node]                 = velocity(xs[node], first);
        }
    std::map<unsigned int, Vec<AD>> xp, vp;
    {
      std::set<unsigned int> primary_nodes;
      for (const unsigned int pf : pair.candidates[e])
        for (const unsigned int node : p.faces[pf])
          primary_nodes.insert(node);
      for (const unsigned int node : primary_nodes)
        {
          const unsigned int first = k;
          xp[node]                 = position(p.reference[node]);
          vp[node]                 = velocity(xp[node], first);
        }
    }
    const AD lambda_0(n, k, state.u(unknowns[k]));
    const AD lambda_1(n, k + 1, state.u(unknowns[k + 1]));

    // nodal normals: average of the adjacent unit face normals
    const auto face_normal = [&](const unsigned int f) {
      return MortarGeometry::face_normal(xs.at(s.faces[f][0]),
                                         xs.at(s.faces[f][1]));
    };
    const auto nodal_normal = [&](const unsigned int node) {
      Vec<AD> sum;
      for (const unsigned int f : s.node_faces[node])
        sum += face_normal(f);
      sum /= MortarGeometry::norm(sum);
      return exact ? sum : constant(sum);
    };
    const Vec<AD> &x0 = xs.at(face[0]), &x1 = xs.at(face[1]);
    const Vec<AD>  n0 = nodal_normal(face[0]), n1 = nodal_normal(face[1]);
    const Vec<AD>  face_n = MortarGeometry::face_normal(x0, x1);
    const AD       half_length = MortarGeometry::norm(Vec<AD>(x1 - x0)) / 2.;

    std::map<types::global_dof_index, AD> rows; // residual contributions
    AD gap[2], weight[2], gap_rate[2];
    for (unsigned int i = 0; i < 2; ++i)
      gap[i] = weight[i] = gap_rate[i] = AD(0.);
    const QGauss<1> gauss(mortar.quadrature_points);

    for (const unsigned int pf : pair.candidates[e])
      {
        const Vec<AD> &y0 = xp.at(p.faces[pf][0]), &y1 = xp.at(p.faces[pf][1]);
        // only faces that face the secondary one
        if (value(MortarGeometry::face_normal(y0, y1)) * value(face_n) >= 0)
          continue;
        double xi_c, xi_d;
        if (!MortarGeometry::project_along_normal_field(
              value(x0), value(x1), value(n0), value(n1), value(y0), xi_c) ||
            !MortarGeometry::project_along_normal_field(
              value(x0), value(x1), value(n0), value(n1), value(y1), xi_d))
          continue;
        const double lo_v = std::max(-1., std::min(xi_c, xi_d));
        const double hi_v = std::min(1., std::max(xi_c, xi_d));
        if (hi_v - lo_v < 1e-12)
          continue;
        const auto end = [&](const double bound, const Vec<AD> &y,
                             const double xi) -> AD {
          if (std::abs(bound - xi) > 0 || !exact)
            return AD(bound);
          return MortarGeometry::project_along_normal_field(x0, x1, n0, n1, y, xi);
        };
        const AD lo = (lo_v == std::min(xi_c, xi_d)) ?
                        end(lo_v, xi_c < xi_d ? y0 : y1, std::min(xi_c, xi_d)) :
                        AD(lo_v);
        const AD hi = (hi_v == std::max(xi_c, xi_d)) ?
                        end(hi_v, xi_c < xi_d ? y1 : y0, std::max(xi_c, xi_d)) :
                        AD(hi_v);

        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const AD xi = lo + (hi - lo) * gauss.point(q)[0];
            const AD JxW = gauss.weight(q) * (hi - lo) * half_length;
            const auto N   = MortarGeometry::shape(xi);
            const auto psi = MortarGeometry::dual_shape(xi);
            const Vec<AD> x = N[0] * x0 + N[1] * x1;
            Vec<AD>       normal = N[0] * n0 + N[1] * n1;
            normal /= MortarGeometry::norm(normal);
            AD eta =
              MortarGeometry::intersect_line_with_face(x, normal, y0, y1);
            if (!exact)
              eta = constant(eta);
            const auto    Np = MortarGeometry::shape(eta);
            const Vec<AD> y  = Np[0] * y0 + Np[1] * y1;
            const AD      g  = (y - x) * normal;
            for (unsigned int i = 0; i < 2; ++i)
              {
                gap[i] += psi[i] * g * JxW;
                weight[i] += N[i] * JxW;
              }
            if (mortar.persistency && state.dynamic)
              {
                const Vec<AD> v_s = N[0] * vs.at(face[0]) + N[1] * vs.at(face[1]);
                const Vec<AD> v_p =
                  Np[0] * vp.at(p.faces[pf][0]) + Np[1] * vp.at(p.faces[pf][1]);
                const AD g_dot = (v_p - v_s) * normal;
                for (unsigned int i = 0; i < 2; ++i)
                  gap_rate[i] += psi[i] * g_dot * JxW;
              }
            // contact traction z = sum_j psi_j lambda_j n_j on both sides
            const Vec<AD> z = AD(psi[0] * lambda_0) * n0 + AD(psi[1] * lambda_1) * n1;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  rows[s.dofs[face[i]][d]] += N[i] * z[d] * JxW;
                  rows[p.dofs[p.faces[pf][i]][d]] -= Np[i] * z[d] * JxW;
                }
          }
      }

    for (const auto &r : rows)
      {
        add_row(r.first, r.second, unknowns, constraints, with_jacobian,
                residual, jacobian);
        residual_full(r.first) += r.second.val();
        force(r.first) += r.second.val();
      }
    for (unsigned int i = 0; i < 2; ++i)
      {
        add_linearized(pair.gap[face[i]], gap[i], unknowns);
        add_linearized(pair.weight[face[i]], weight[i], unknowns);
        add_linearized(pair.gap_rate[face[i]], gap_rate[i], unknowns);
      }
  }

  template <int dim>
  void
  MortarContact<dim>::assemble(const TrialState                &state,
                               const AffineConstraints<double> &constraints,
                               const bool                       with_jacobian,
                               VectorType                      &residual,
                               MatrixType                      &jacobian,
                               VectorType                      &residual_full)
  {
    if (force.size() != state.u.size())
      {
        force.reinit(state.u);
        force_committed.reinit(state.u);
      }
    force          = 0;
    last_u         = &state.u;
    bool changed   = false;
    n_active       = 0;
    total_force[0] = total_force[1] = 0;

    for (auto &pair : pairs)
      {
        const unsigned int n_nodes = pair.secondary.n_nodes();
        pair.gap.assign(n_nodes, LinearizedValue());
        pair.weight.assign(n_nodes, LinearizedValue());
        pair.gap_rate.assign(n_nodes, LinearizedValue());
        for (unsigned int e = 0; e < pair.secondary.n_faces(); ++e)
          assemble_face(pair, e, state, constraints, with_jacobian, residual,
                        jacobian, residual_full);

        // the complementarity condition of every secondary node, scaled by
        // its reference weight so that its row has force units
        for (unsigned int j = 0; j < n_nodes; ++j)
          {
            NodeState                    &node = pair.nodes[j];
            const types::global_dof_index row  = pair.secondary.dofs[j][dim];
            const double scale  = pair.secondary.reference_weight[j];
            const double lambda = state.u(row);
            node.pressure       = lambda;
            node.weighted_gap   = pair.gap[j].value;
            node.weight         = pair.weight[j].value;
            node.projected      = node.weight > 1e-12 * scale;

            // the constraint quantity c * gtilde and its derivatives
            LinearizedValue constraint;
            bool            active = false;
            if (node.projected)
              {
                const bool rate = node.persistent && state.dynamic;
                const LinearizedValue &g = rate ? pair.gap_rate[j] : pair.gap[j];
                const double factor = mortar.c_n * (rate ? state.dt : 1.);
                const double w      = mortar.normalize_c_n ? node.weight : 1.;
                constraint.value    = factor * g.value / w;
                for (const auto &d : g.derivatives)
                  constraint.derivatives[d.first] += factor * d.second / w;
                if (mortar.normalize_c_n)
                  for (const auto &d : pair.weight[j].derivatives)
                    constraint.derivatives[d.first] -=
                      factor * g.value * d.second / (w * w);
                active = (lambda - constraint.value > 0);
              }
            if (active != node.active)
              changed = true;
            node.active = active;
            if (active)
              ++n_active;
            if (constraints.is_constrained(row))
              continue;
            if (active)
              {
                residual(row) += scale * constraint.value;
                if (with_jacobian)
                  for (const auto &d : constraint.derivatives)
                    if (!constraints.is_constrained(d.first))
                      jacobian.add(row, d.first, scale * d.second);
              }
            else
              {
                residual(row) += scale * lambda;
                if (with_jacobian)
                  jacobian.add(row, row, scale);
              }
          }
        for (unsigned int j = 0; j < n_nodes; ++j)
          for (unsigned int d = 0; d < 2; ++d)
            total_force[d] -= force(pair.secondary.dofs[j][d]);
      }
    residual.compress(VectorOperation::add);
    residual_full.compress(VectorOperation::add);
    if (with_jacobian)
      jacobian.compress(VectorOperation::add);
    active_set_changed = changed;
  }

  template <int dim>
  void
  MortarContact<dim>::commit_step(const VectorType &old_u, const double time)
  {
    Assert(last_u != nullptr, ExcInternalError());
    // work of the contact forces on the bodies, trapezoidal in time
    double work = 0;
    for (const auto &pair : pairs)
      {
        std::set<types::global_dof_index> dofs;
        for (const auto *surface : {&pair.secondary, &pair.primary})
          for (const auto &node_dofs : surface->dofs)
            for (unsigned int d = 0; d < dim; ++d)
              dofs.insert(node_dofs[d]);
        for (const auto i : dofs)
          work -= ((*last_u)(i) - old_u(i)) * 0.5 *
                  (force(i) + (have_state ? force_committed(i) : 0.));
      }
    contact_work += work;
    force_committed = force;
    committed_u     = *last_u;
    gap_field       = 0;
    have_state      = true;

    for (auto &pair : pairs)
      for (unsigned int j = 0; j < pair.nodes.size(); ++j)
        {
          NodeState &node = pair.nodes[j];
          node.gap_at_commit =
            node.projected ? node.weighted_gap / node.weight : 1e300;
          if (node.projected)
            gap_field(pair.secondary.dofs[j][dim]) = node.gap_at_commit;
          node.persistent = mortar.persistency && node.projected &&
                            node.gap_at_commit <= mortar.capture_tolerance;
        }

    if (history)
      {
        *history << std::setprecision(10) << time;
        for (const auto &m : monitored)
          {
            const NodeState &node = pairs[m.first].nodes[m.second];
            *history << ',' << node.pressure << ','
                     << (node.projected ? node.weighted_gap / node.weight : 0.);
          }
        *history << std::endl;
      }
  }

  template <int dim>
  std::vector<std::string>
  MortarContact<dim>::statistics_columns() const
  {
    return {"active_contact_nodes",
            "contact_force_x",
            "contact_force_y",
            "contact_work"};
  }

  template <int dim>
  std::vector<double>
  MortarContact<dim>::statistics() const
  {
    return {double(n_active), total_force[0], total_force[1], contact_work};
  }

  template <int dim>
  void
  MortarContact<dim>::write_output(const std::string &dir,
                                   const unsigned int step)
  {
    std::ofstream out(dir + "/contact_surface-" +
                      Utilities::int_to_string(step, 5) + ".csv");
    out << "pair,node,x,y,normalized_weighted_gap,pressure,active\n";
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const auto               &s = pairs[p].secondary;
        std::vector<unsigned int> order(s.n_nodes());
        for (unsigned int j = 0; j < order.size(); ++j)
          order[j] = j;
        std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
          return s.reference[a][0] < s.reference[b][0] ||
                 (s.reference[a][0] == s.reference[b][0] &&
                  s.reference[a][1] < s.reference[b][1]);
        });
        for (const unsigned int j : order)
          {
            const NodeState &node = pairs[p].nodes[j];
            const Point<dim> x =
              have_state ? s.position(j, committed_u) : s.reference[j];
            out << p << ',' << j << ',' << std::setprecision(10) << x[0] << ','
                << x[1] << ','
                << (node.projected ? node.weighted_gap / node.weight : 0.)
                << ',' << node.pressure << ',' << node.active << '\n';
          }
      }
  }

  template class MortarContact<2>;
  template class MortarContact<3>;
} // namespace ContactDynamics
