// The forces of one contact patch (a secondary face for mortar, a
// secondary node for node-to-segment) as a formulation computes them.
#ifndef contact_dynamics_contact_patch_forces_h
#define contact_dynamics_contact_patch_forces_h

#include <deal.II/base/types.h>

#include <array>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  /**
   * The forces of one patch in the order a formulation computes them;
   * SurfaceContact adds them to the system (or, for a patch assembled
   * for its gaps only, drops them).
   */
  struct PatchForces
  {
    using Derivatives = std::vector<std::pair<types::global_dof_index, double>>;

    /** A residual row of a contact force with its derivatives. */
    void
    add(const types::global_dof_index row,
        const double                  value,
        Derivatives                 &&derivatives)
    {
      rows.push_back({row, value, std::move(derivatives)});
    }

    /**
     * The mortar normal force rows -sum_j lambda_j direction[i][j] of the
     * positions i (the first direction.size() unknowns), with their
     * derivatives in the multipliers (the unknowns that follow the
     * positions) and, unless `hessian` is empty, in the positions
     * (hessian[i n + l]); extra(i, derivatives) may add more.
     */
    template <std::size_t n_nodes, typename Extra>
    void
    add_normal_rows(const std::vector<types::global_dof_index>     &unknowns,
                    const std::array<double, n_nodes>              &lambda,
                    const std::vector<std::array<double, n_nodes>> &direction,
                    const std::vector<double>                      &hessian,
                    const Extra                                    &extra)
    {
      const unsigned int n_positions = direction.size();
      for (unsigned int i = 0; i < n_positions; ++i)
        {
          Derivatives derivatives;
          double      value = 0;
          for (unsigned int j = 0; j < n_nodes; ++j)
            {
              value -= lambda[j] * direction[i][j];
              if (direction[i][j] != 0)
                derivatives.emplace_back(unknowns[n_positions + j],
                                         -direction[i][j]);
            }
          if (!hessian.empty())
            for (unsigned int l = 0; l < n_positions; ++l)
              if (const double h = hessian[i * n_positions + l]; h != 0)
                derivatives.emplace_back(unknowns[l], -h);
          extra(i, derivatives);
          if (value != 0 || !derivatives.empty())
            add(unknowns[i], value, std::move(derivatives));
        }
    }

    /** Records the tangential (friction) part of a force row. */
    void
    add_tangential(const types::global_dof_index row, const double value)
    {
      tangential.emplace_back(row, value);
    }

    struct Row
    {
      types::global_dof_index row;
      double                  value;
      Derivatives             derivatives;
    };
    std::vector<Row>                                        rows;
    std::vector<std::pair<types::global_dof_index, double>> tangential;
  };
} // namespace ContactDynamics

#endif
