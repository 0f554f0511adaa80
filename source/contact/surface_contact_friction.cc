// SurfaceContact: Coulomb friction at the secondary nodes (paper equation
// 8) in its semi-smooth form, with the tangential directions that the
// supports of both bodies hold (a symmetry plane) taken out.
#include <deal.II/base/exceptions.h>

#include <contact_dynamics/contact/surface_contact.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ContactDynamics
{
  namespace
  {
    // Adds the derivatives of -mu xi e_a through the slip direction
    // e = s / |s|, d e / d s = (I - e e^T) / |s|, to the slip row of
    // tangent a (in 2-D e is a sign: none).
    template <unsigned int n_t>
    void
    add_direction_derivatives(
      std::map<types::global_dof_index, double>      &row,
      const unsigned int                              a,
      const std::array<types::global_dof_index, n_t> &rows,
      const std::array<LinearizedValue, n_t>         &v,
      const std::array<double, n_t>                  &e,
      const double                                    mu,
      const double                                    xi,
      const double                                    trial_norm,
      const double                                    c_t)
    {
      for (unsigned int b = 0; b < n_t; ++b)
        {
          const double curvature =
            -mu * xi * ((a == b ? 1. : 0.) - e[a] * e[b]) / trial_norm;
          row[rows[b]] += curvature;
          for (const auto &d : v[b].derivatives)
            row[d.first] += curvature * c_t * d.second;
        }
    }

    // The tangential directions a node's supports hold: combinations of
    // its slip rates whose rows lie (to 10 % of their norm) on dofs held by
    // Dirichlet conditions (a node on a symmetry plane of both bodies,
    // along its normal to the plane; what remains there is the exact
    // Jacobian's turn of the tangents). Their stick rows would be zero or
    // nearly and their multipliers undetermined: such a combination carries
    // no friction (its force goes into the supports). A direction held on
    // one side only (a prescribed sliding of the secondary) keeps its
    // friction: the other side's dofs carry its row. Returns the number
    // held and an orthonormal basis q of the tangential components, the
    // held directions first.
    template <unsigned int n_t>
    unsigned int
    held_candidates(const std::array<LinearizedValue, n_t>   &v,
                    const AffineConstraints<double>          &constraints,
                    std::array<std::array<double, n_t>, n_t> &q)
    {
      constexpr double held_fraction = 1e-2; // of the squared row norm
      // the Gram matrices A of the rows and F of their free parts (a
      // hanging dof is free: its parents carry its rows)
      std::array<std::array<double, n_t>, n_t>                   A{}, F{};
      std::map<types::global_dof_index, std::array<double, n_t>> columns;
      for (unsigned int a = 0; a < n_t; ++a)
        for (const auto &[dof, x] : v[a].derivatives)
          columns[dof][a] += x;
      for (const auto &[dof, x] : columns)
        {
          const auto *entries = constraints.is_constrained(dof) ?
                                  constraints.get_constraint_entries(dof) :
                                  nullptr;
          const bool  held    = entries != nullptr && entries->empty();
          for (unsigned int a = 0; a < n_t; ++a)
            for (unsigned int b = 0; b < n_t; ++b)
              {
                A[a][b] += x[a] * x[b];
                if (!held)
                  F[a][b] += x[a] * x[b];
              }
        }
      q = {};
      for (unsigned int a = 0; a < n_t; ++a)
        q[a][a] = 1;
      if (n_t == 1)
        return A[0][0] > 0 && F[0][0] <= held_fraction * A[0][0] ? 1 : 0;
      // the fractions r of F q = r A q: det(F - r A) = a2 r^2 + a1 r + a0
      const unsigned int last = n_t - 1; // (1: the code is 3-D's)
      const double       a2 = A[0][0] * A[last][last] - A[0][last] * A[0][last];
      const double a1 = -(F[0][0] * A[last][last] + F[last][last] * A[0][0] -
                          2 * F[0][last] * A[0][last]);
      const double a0 = F[0][0] * F[last][last] - F[0][last] * F[0][last];
      if (!(a2 > 1e-12 * (A[0][0] * A[last][last])))
        return 0; // the rows are dependent on all dofs: not held ones
      const double root     = std::sqrt(std::max(a1 * a1 - 4 * a2 * a0, 0.));
      const double smallest = (-a1 - root) / (2 * a2),
                   largest  = (-a1 + root) / (2 * a2);
      if (smallest > held_fraction)
        return 0;
      if (largest <= held_fraction)
        return 2;
      // the held direction: the null vector of F - smallest A
      const double m00        = F[0][0] - smallest * A[0][0],
                   m01        = F[0][last] - smallest * A[0][last],
                   m11        = F[last][last] - smallest * A[last][last];
      std::array<double, 2> h = {{m01, -m00}};
      if (std::hypot(m11, m01) > std::hypot(m01, m00))
        h = {{m11, -m01}};
      const double norm = std::hypot(h[0], h[1]);
      q[0][0]           = h[0] / norm;
      q[0][last]        = h[1] / norm;
      q[last][0]        = -q[0][last];
      q[last][last]     = q[0][0];
      return 1;
    }

    template <unsigned int n>
    double
    dot(const std::array<double, n> &x, const std::array<double, n> &y)
    {
      double sum = 0;
      for (unsigned int a = 0; a < n; ++a)
        sum += x[a] * y[a];
      return sum;
    }

    // the dofs of node j's tangential multipliers
    template <int dim>
    std::array<types::global_dof_index, dim - 1>
    tangential_rows(const ContactPairData<dim> &pair, const unsigned int j)
    {
      std::array<types::global_dof_index, dim - 1> rows;
      for (unsigned int a = 0; a + 1 < dim; ++a)
        rows[a] = pair.secondary.dofs[j][dim + 1 + a];
      return rows;
    }

    template <unsigned int n>
    std::array<double, n>
    values_at(const std::array<types::global_dof_index, n> &dofs,
              const TrilinosWrappers::MPI::Vector          &u)
    {
      std::array<double, n> values;
      for (unsigned int a = 0; a < n; ++a)
        values[a] = u(dofs[a]);
      return values;
    }

    // The held_candidates() along which the node does not slide (to 10 %
    // of its slip rate, or below `negligible`): against a rigid obstacle,
    // whose side has no dofs, a direction that depends on the secondary's
    // Dirichlet dofs only but moves (a surface driven along the obstacle)
    // is driven, not held, and keeps its friction.
    template <unsigned int n_t>
    unsigned int
    held_tangents(const std::array<LinearizedValue, n_t>   &v,
                  const AffineConstraints<double>          &constraints,
                  const double                              negligible,
                  std::array<std::array<double, n_t>, n_t> &q)
    {
      const unsigned int n_held = held_candidates<n_t>(v, constraints, q);
      double             rate   = 0;
      for (unsigned int a = 0; a < n_t; ++a)
        rate += v[a].value * v[a].value;
      rate = std::sqrt(rate);
      for (unsigned int a = 0; a < n_held; ++a)
        {
          double along = 0;
          for (unsigned int b = 0; b < n_t; ++b)
            along += q[a][b] * v[b].value;
          if (std::abs(along) > std::max(0.1 * rate, negligible))
            return 0;
        }
      return n_held;
    }

    // A slip rate that held_tangents() may ignore: none for a meshed pair,
    // whose held direction is held on both sides; against an obstacle, one
    // that does not change the stick test |s| < mu xi
    template <int dim>
    double
    negligible_rate(const ContactPairData<dim> &pair,
                    const double                xi,
                    const double                c_t)
    {
      return pair.obstacle ? 1e-6 * pair.friction_coefficient * xi / c_t :
                             HUGE_VAL;
    }

    // Friction at a node with held tangential directions (held_tangents()):
    // in the basis q no multiplier along them, along the free one (3-D, one
    // held) Coulomb's law in one dimension. Returns whether the node sticks.
    template <int dim, unsigned int n_t>
    bool
    assemble_held_friction(ContactPairData<dim> &pair,
                           const unsigned int    j,
                           const unsigned int    n_held,
                           const std::array<std::array<double, n_t>, n_t> &q,
                           const std::array<LinearizedValue, n_t>         &v,
                           const double                                    xi,
                           const LinearizedValue               &constraint,
                           const TrilinosWrappers::MPI::Vector &u,
                           const double                         c_t,
                           const ContactLinearSystem           &system)
    {
      const auto   rows     = tangential_rows<dim>(pair, j);
      const auto   lambda_t = values_at<n_t>(rows, u);
      const double scale    = pair.secondary.reference_weight[j];
      const double mu       = pair.friction_coefficient;
      // (held in every direction: it cannot slide)
      bool stick = n_held == n_t;
      for (unsigned int a = 0; a < n_t; ++a)
        {
          std::map<types::global_dof_index, double> row;
          double                                    lambda = 0, rate = 0;
          for (unsigned int b = 0; b < n_t; ++b)
            {
              lambda += q[a][b] * lambda_t[b];
              rate += q[a][b] * v[b].value;
            }
          const double trial    = lambda + c_t * rate;
          double       residual = lambda;
          if (a >= n_held && (std::abs(trial) < mu * xi || trial == 0))
            {
              stick    = true;
              residual = c_t * rate;
              for (unsigned int b = 0; b < n_t; ++b)
                for (const auto &d : v[b].derivatives)
                  row[d.first] += c_t * q[a][b] * d.second;
            }
          else
            {
              for (unsigned int b = 0; b < n_t; ++b)
                row[rows[b]] += q[a][b];
              if (a >= n_held)
                {
                  // slip: lambda - mu xi sign(s)
                  const double e = trial > 0 ? 1. : -1.;
                  residual -= mu * xi * e;
                  row[pair.secondary.dofs[j][dim]] -= mu * e;
                  for (const auto &d : constraint.derivatives)
                    row[d.first] += mu * e * d.second;
                }
            }
          system.residual(rows[a]) += scale * residual;
          if (system.with_jacobian)
            system.add_row(rows[a], row, scale);
        }
      return stick;
    }
  } // namespace

  template <int dim>
  std::array<LinearizedValue, dim - 1>
  SurfaceContact<dim>::normalized_slip_rates(PairData          &pair,
                                             const unsigned int j,
                                             const VectorType  &u) const
  {
    // the slip rates divided by the node's weight (if c_n is normalized);
    // the node's state shows them and the tangential multipliers
    NodeState                           &node = pair.nodes[j];
    std::array<LinearizedValue, dim - 1> v;
    const double                         w =
      (complementarity.normalize_c_n && node.projected) ? node.weight : 1.;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      {
        const double lambda_t       = u(pair.secondary.dofs[j][dim + 1 + a]);
        const LinearizedValue &slip = pair.slip_rate[j][a];
        v[a].value                  = slip.value / w;
        for (const auto &d : slip.derivatives)
          v[a].derivatives[d.first] += d.second / w;
        if (complementarity.normalize_c_n && node.projected)
          for (const auto &d : pair.weight[j].derivatives)
            v[a].derivatives[d.first] -= slip.value * d.second / (w * w);
        node.tangential[a] = lambda_t * traction_per_multiplier(pair, j, u);
        node.slip_rate[a]  = v[a].value;
      }
    return v;
  }

  template <int dim>
  void
  SurfaceContact<dim>::assemble_friction(PairData              &pair,
                                         const unsigned int     j,
                                         const bool             active,
                                         const LinearizedValue &constraint,
                                         const VectorType      &u,
                                         const LinearSystem    &system)
  {
    // Coulomb friction (paper equation 8) in its semi-smooth form, for the
    // vector lambda_t of the dim - 1 tangential multipliers: with
    // xi = lambda_n - c_n g (the normal argument) and s = lambda_t + c_t v,
    //   inactive:           lambda_t = 0
    //   stick (|s| < mu xi): v = 0 (written c_t v = 0)
    //   slip:               lambda_t - mu xi s / |s| = 0
    // (the slip direction from the trial traction s, as in Hueeber, Stadler
    // and Wohlmuth 2008; in 2-D s / |s| is its sign)
    constexpr unsigned int        n_t   = dim - 1;
    NodeState                    &node  = pair.nodes[j];
    const double                  scale = pair.secondary.reference_weight[j];
    const double                  mu    = pair.friction_coefficient;
    const types::global_dof_index normal_row = pair.secondary.dofs[j][dim];
    const double                  lambda_n   = u(normal_row);
    const auto                    rows       = tangential_rows<dim>(pair, j);
    const auto                    lambda_t   = values_at<n_t>(rows, u);
    const std::array<LinearizedValue, n_t> v =
      normalized_slip_rates(pair, j, u);
    node.stick = false;
    if (system.constraints.is_constrained(rows[0]))
      return;

    const double            xi = lambda_n - constraint.value;
    std::array<double, n_t> trial;
    for (unsigned int a = 0; a < n_t; ++a)
      trial[a] = lambda_t[a] + complementarity.c_t * v[a].value;
    const double trial_norm = std::sqrt(dot<n_t>(trial, trial));
    if (!active)
      {
        for (unsigned int a = 0; a < n_t; ++a)
          {
            system.residual(rows[a]) += scale * lambda_t[a];
            if (system.with_jacobian)
              system.jacobian.add(rows[a], rows[a], scale);
          }
        return;
      }
    std::array<std::array<double, n_t>, n_t> q;
    const double tiny = negligible_rate(pair, xi, complementarity.c_t);
    if (const auto n_held = held_tangents<n_t>(v, system.constraints, tiny, q))
      {
        node.stick = assemble_held_friction<dim, n_t>(pair,
                                                      j,
                                                      n_held,
                                                      q,
                                                      v,
                                                      xi,
                                                      constraint,
                                                      u,
                                                      complementarity.c_t,
                                                      system);
        ++(node.stick ? n_stick : n_slip);
        return;
      }
    // (|s| = 0 sticks: active means xi > 0, unless mu xi underflows)
    if (trial_norm < mu * xi || trial_norm == 0)
      {
        node.stick = true;
        ++n_stick;
        for (unsigned int a = 0; a < n_t; ++a)
          {
            system.residual(rows[a]) +=
              scale * complementarity.c_t * v[a].value;
            if (system.with_jacobian)
              system.add_row(rows[a],
                             v[a].derivatives,
                             scale * complementarity.c_t);
          }
        return;
      }
    ++n_slip;
    // d(s / |s|)/ds = (I - e e^T) / |s|, e = s / |s|: zero in 2-D
    std::array<double, n_t> e;
    for (unsigned int a = 0; a < n_t; ++a)
      e[a] = trial[a] / trial_norm;
    for (unsigned int a = 0; a < n_t; ++a)
      {
        system.residual(rows[a]) += scale * (lambda_t[a] - mu * xi * e[a]);
        if (!system.with_jacobian)
          continue;
        std::map<types::global_dof_index, double> row;
        row[rows[a]] += 1.;
        row[normal_row] -= mu * e[a];
        for (const auto &d : constraint.derivatives)
          row[d.first] += mu * e[a] * d.second;
        if (dim == 3)
          add_direction_derivatives<n_t>(row,
                                         a,
                                         rows,
                                         v,
                                         e,
                                         mu,
                                         xi,
                                         trial_norm,
                                         complementarity.c_t);
        system.add_row(rows[a], row, scale);
      }
  }

#define INSTANTIATE(dim)                                                              \
  template std::array<LinearizedValue, dim - 1>                                       \
                SurfaceContact<dim>::normalized_slip_rates(PairData &,                \
                                             const unsigned int,        \
                                             const VectorType &) const; \
  template void SurfaceContact<dim>::assemble_friction(                               \
    PairData &,                                                                       \
    const unsigned int,                                                               \
    const bool,                                                                       \
    const LinearizedValue &,                                                          \
    const VectorType &,                                                               \
    const LinearSystem &);

  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace ContactDynamics
