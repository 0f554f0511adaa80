// 3-D dual mortar contact between two meshed surfaces whose faces are
// 9-node quadrilaterals (elements of degree 2). A patch is a secondary
// face: its segments with the candidate primary faces are integrated on
// the curved faces (quadratic_segment_3d.h), the gap measured along the
// secondary face's own unit normal. The dual basis is that of the covered
// part, for the multiplier functions of the nodes kept (multiplier_map(),
// as in 2-D: a node whose covered integral is below 10 % of its whole-face
// one is spread onto the others so that the functions still sum to one
// and reproduce linear fields).
//
// Derivatives are chained as for faces of degree 1
// (mortar_face_3d_hessian.cc): each segment's moments in its 54 variables
// (the two faces' positions), the normalized gaps in the face's moments;
// second derivatives by reverse over forward mode for the one weighted sum
// of the moments the normal force needs.
#include <deal.II/base/quadrature_lib.h>

#include <contact_dynamics/contact/contact_ad.h>
#include <contact_dynamics/contact/kept_multiplier_nodes.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/quadratic_mortar_face_3d.h>
#include <contact_dynamics/contact/reverse_hessian_sweep.h>

#include <algorithm>
#include <map>
#include <set>

namespace ContactDynamics
{
  namespace
  {
    using namespace QuadraticSegment3D;

    // the patch's nodes: the face's 9 (first), with friction the other
    // secondary nodes of the faces around them (their nodal normals), then
    // the candidates' primary nodes; node k's position is entries 3 k to
    // 3 k + 2
    template <typename PairData>
    std::vector<std::pair<bool, unsigned int>>
    patch_nodes_3d(const PairData                  &pair,
                   const unsigned int               e,
                   const std::vector<unsigned int> &faces)
    {
      const auto                                &s = pair.secondary;
      std::vector<std::pair<bool, unsigned int>> nodes;
      for (const unsigned int n : s.face_nodes[e])
        nodes.emplace_back(true, n);
      if (pair.friction_coefficient > 0)
        {
          std::set<unsigned int> ring;
          for (const unsigned int n : s.face_nodes[e])
            for (const unsigned int f : s.node_faces[n])
              ring.insert(s.face_nodes[f].begin(), s.face_nodes[f].end());
          for (const unsigned int n : s.face_nodes[e])
            ring.erase(n);
          for (const unsigned int n : ring)
            nodes.emplace_back(true, n);
        }
      std::set<unsigned int> primary;
      for (const unsigned int f : faces)
        primary.insert(pair.primary.face_nodes[f].begin(),
                       pair.primary.face_nodes[f].end());
      for (const unsigned int n : primary)
        nodes.emplace_back(false, n);
      return nodes;
    }

    template <typename Number>
    void
    face_positions(const std::vector<double>       &x,
                   const std::array<unsigned, n_v> &index,
                   const unsigned int               first,
                   const double                     c_v,
                   const bool                       velocity,
                   Face<Number>                    &y)
    {
      for (unsigned int a = 0; a < 9; ++a)
        for (unsigned int d = 0; d < 3; ++d)
          {
            const unsigned int v     = first + 3 * a + d;
            const double       value = x[index[v]];
            if constexpr (std::is_same_v<Number, double>)
              y[a][d] = value;
            else if (velocity)
              y[a][d] = c_v * Number(n_v, v, 0.) + value;
            else
              y[a][d] = Number(n_v, v, value);
          }
    }

    // the moments of every covering segment and their gradients
    template <typename PairData>
    FaceMoments
    face_moments(const PairData                                   &pair,
                 const unsigned int                                e,
                 const std::vector<std::pair<bool, unsigned int>> &nodes,
                 const std::vector<double>                        &position,
                 const std::vector<double>                        &velocity,
                 const double                                      c_v,
                 const bool                                        rates,
                 const TriangleRule                               &rule,
                 const unsigned int                                edge_points,
                 const bool                                        friction)
    {
      // (edges that finer faces hang on: their points, so that the
      // segments of coarse and fine primary faces tile)
      const auto points_of = [&](const unsigned int pf) {
        EdgePoints points;
        for (unsigned int i = 0; i < 4; ++i)
          points[i] = edge_points * (pair.primary_edge_subdivisions.empty() ?
                                       1 :
                                       pair.primary_edge_subdivisions[pf][i]);
        return points;
      };
      using AD                                 = Sacado::Fad::SFad<double, n_v>;
      const unsigned int                   n_x = position.size();
      std::map<unsigned int, unsigned int> primary_index;
      for (unsigned int k = 9; k < nodes.size(); ++k)
        if (!nodes[k].first)
          primary_index[nodes[k].second] = 3 * k;
      FaceMoments result;
      result.gradient.assign(n_moments * n_x, 0.);
      for (const unsigned int pf : pair.candidates[e])
        {
          std::array<unsigned, n_v> index;
          for (unsigned int v = 0; v < 27; ++v)
            index[v] = v;
          for (unsigned int a = 0; a < 9; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              index[27 + 3 * a + d] =
                primary_index.at(pair.primary.face_nodes[pf][a]) + d;
          Face<AD> xs, xm, vs, vm;
          face_positions(position, index, 0, c_v, false, xs);
          face_positions(position, index, 27, c_v, false, xm);
          face_positions(velocity, index, 0, c_v, true, vs);
          face_positions(velocity, index, 27, c_v, true, vm);
          // faces that look the same way are not a contact pair's
          const auto ns = cross(combine(values(xs), shape(0.5, 0.5).dN[0]),
                                combine(values(xs), shape(0.5, 0.5).dN[1]));
          const auto nm = cross(combine(values(xm), shape(0.5, 0.5).dN[0]),
                                combine(values(xm), shape(0.5, 0.5).dN[1]));
          if (ns * nm >= 0)
            continue;
          std::array<AD, n_moments> m;
          std::array<AD, 81>        P;
          const EdgePoints          points = points_of(pf);
          const bool                ok     = segment_moments(xs,
                                          xm,
                                          rule,
                                          points,
                                          rates ? &vs : nullptr,
                                          rates ? &vm : nullptr,
                                          m,
                                          friction ? &P : nullptr);
          if (!ok || value_of(m[9] + m[10] + m[11] + m[12] + m[13] + m[14] +
                              m[15] + m[16] + m[17]) <= 0)
            continue;
          result.covering.push_back(pf);
          result.variables.push_back(index);
          result.edge_points.push_back(points);
          if (friction)
            {
              auto &values = result.coupling.emplace_back();
              auto &d      = result.d_coupling.emplace_back();
              for (unsigned int q = 0; q < 81; ++q)
                {
                  values[q] = P[q].val();
                  for (int v = 0; v < n_v; ++v)
                    d[q][v] = P[q].dx(v);
                }
            }
          for (unsigned int q = 0; q < n_moments; ++q)
            {
              result.total[q] += m[q].val();
              for (int v = 0; v < n_v; ++v)
                result.gradient[q * n_x + index[v]] += m[q].dx(v);
            }
        }
      return result;
    }

    /**
     * The multiplier functions N'_j = sum_k T_jk N_k of a face of degree 2
     * on its covered part (the 3-D form of the 2-D multiplier_map() of
     * mortar_contact_quadratic.cc): a node whose covered D_j is below 10 %
     * of its whole-face D_j leaves the face's multipliers, its function
     * spread onto the nodes kept with the weights of least norm that
     * reproduce the linear functions of the face's coordinates (fewer
     * conditions where the kept nodes lie on a line or are one).
     */
    Map9
    multiplier_map(const Face<double> &x, const std::array<double, 9> &covered)
    {
      std::array<double, 9> whole{};
      const QGauss<1>       gauss(3);
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          {
            const auto   s = shape(gauss.point(a)[0], gauss.point(b)[0]);
            const double J =
              norm(cross(combine(x, s.dN[0]), combine(x, s.dN[1])));
            for (unsigned int j = 0; j < 9; ++j)
              whole[j] += s.N[j] * gauss.weight(a) * gauss.weight(b) * J;
          }
      const auto kept  = kept_multiplier_nodes(covered, whole);
      const auto nodes = QuadraticFace::node_coordinates<3>();
      Map9       T{};
      for (const unsigned int j : kept)
        T[j][j] = 1.;
      for (unsigned int d = 0; d < 9; ++d)
        if (T[d][d] == 0)
          {
            // conditions sum c = 1 and sum c xi_k = xi_d (and eta) on the
            // kept nodes, as many as are independent: c = K^T (K K^T)^-1 r
            const unsigned int axis =
              std::any_of(kept.begin(),
                          kept.end(),
                          [&](const unsigned int k) {
                            return nodes[k][0] != nodes[kept[0]][0];
                          }) ?
                0 :
                1;
            for (unsigned int n_c = 3; n_c >= 1; --n_c)
              {
                // (two conditions: along the coordinate the kept nodes span)
                const auto row = [&](const unsigned int c, const unsigned k) {
                  return c == 0 ? 1. : nodes[k][n_c == 3 ? c - 1 : axis];
                };
                std::array<std::array<double, 3>, 3> KK{};
                std::array<double, 3>                r{};
                for (unsigned int c = 0; c < n_c; ++c)
                  {
                    r[c] = row(c, d);
                    for (unsigned int c2 = 0; c2 < n_c; ++c2)
                      for (const unsigned int k : kept)
                        KK[c][c2] += row(c, k) * row(c2, k);
                  }
                for (unsigned int c = n_c; c < 3; ++c)
                  KK[c][c] = 1.;
                const double det =
                  KK[0][0] * (KK[1][1] * KK[2][2] - KK[1][2] * KK[2][1]) -
                  KK[0][1] * (KK[1][0] * KK[2][2] - KK[1][2] * KK[2][0]) +
                  KK[0][2] * (KK[1][0] * KK[2][1] - KK[1][1] * KK[2][0]);
                if (std::abs(det) < 1e-10)
                  continue;
                const auto z = solve<double, 3>(KK, r);
                for (const unsigned int k : kept)
                  for (unsigned int c = 0; c < n_c; ++c)
                    T[k][d] += z[c] * row(c, k);
                break;
              }
          }
      return T;
    }

    // the normalized gaps h_j = (M'^-1 G')_j, weights w_j = D'_j and rates
    // -w_j (M'^-1 R')_j of the kept nodes' functions N' = T N, from the
    // face's moments (Number: their derivatives in the moments)
    template <typename Number>
    struct FaceValues
    {
      std::array<Number, 9> ratio, weight, rate;
    };

    // the 54 moments the normalized gaps depend on: G (0 to 8), M (18 to 62)
    constexpr unsigned int
    gap_variable(const unsigned int a)
    {
      return a < 9 ? a : a + 9;
    }

    template <typename Number>
    FaceValues<Number>
    face_values(const std::array<Number, n_moments> &m, const Map9 &T)
    {
      const auto            K = primed_inverse(m, T);
      std::array<Number, 9> G, D, R;
      for (unsigned int j = 0; j < 9; ++j)
        {
          G[j] = D[j] = R[j] = Number(0.);
          for (unsigned int k = 0; k < 9; ++k)
            if (T[j][k] != 0)
              {
                G[j] += T[j][k] * m[k];
                D[j] += T[j][k] * m[9 + k];
                R[j] += T[j][k] * m[n_gap_moments + k];
              }
        }
      FaceValues<Number> f;
      for (unsigned int j = 0; j < 9; ++j)
        {
          f.ratio[j] = f.rate[j] = Number(0.);
          for (unsigned int k = 0; k < 9; ++k)
            {
              f.ratio[j] += K[j][k] * G[k];
              f.rate[j] -= K[j][k] * R[k];
            }
          f.weight[j] = D[j];
          f.rate[j] *= D[j];
        }
      return f;
    }

    /**
     * For psi = sum_j c_j h_j with c_j = lambda_j w_j held fixed and h =
     * K G' (face_values()): its gradient in the moments (c) and its
     * Hessian B in the 54 it depends on (gap_variable()), in closed form.
     * With a = K c and the pull-backs a~ = T^T a, h~ = T^T h, K~ = T^T K T,
     * a moment M_jl entering as dM = E_jl (the symmetric unit matrix) and
     * G_k as dG = e_k: dpsi = a~ . dG - a~^T dM h~ and d2psi =
     * -a~^T dM1 K~ dG2 - a~^T dM2 K~ dG1 + a~^T dM2 K~ dM1 h~ +
     * a~^T dM1 K~ dM2 h~.
     */
    void
    ratio_derivatives(const std::array<double, n_moments> &total,
                      const Map9                          &T,
                      const std::array<double, 9>         &c_node,
                      const std::array<double, 9>         &h,
                      std::array<double, n_moments>       &c,
                      std::vector<double>                 &B)
    {
      const auto            K = primed_inverse(total, T);
      std::array<double, 9> a{}, at{}, ht{};
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int k = 0; k < 9; ++k)
          a[j] += K[j][k] * c_node[k];
      Map9 Kt{};
      for (unsigned int j = 0; j < 9; ++j)
        for (unsigned int k = 0; k < 9; ++k)
          if (T[j][k] != 0)
            {
              at[k] += T[j][k] * a[j];
              ht[k] += T[j][k] * h[j];
              for (unsigned int l = 0; l < 9; ++l)
                for (unsigned int r = 0; r < 9; ++r)
                  Kt[k][r] += T[j][k] * K[j][l] * T[l][r];
            }
      // the entries (p, q) of E of moment variable v (none for G)
      std::array<std::vector<std::pair<unsigned, unsigned>>, 54> E;
      for (unsigned int j = 0, v = 9; j < 9; ++j)
        for (unsigned int l = j; l < 9; ++l, ++v)
          {
            E[v].emplace_back(j, l);
            if (l != j)
              E[v].emplace_back(l, j);
          }
      c.fill(0.);
      for (unsigned int v = 0; v < 54; ++v)
        {
          if (v < 9)
            c[v] = at[v];
          for (const auto &[p, q] : E[v])
            c[gap_variable(v)] -= at[p] * ht[q];
        }
      B.assign(54 * 54, 0.);
      for (unsigned int v = 9; v < 54; ++v)
        {
          for (unsigned int k = 0; k < 9; ++k)
            {
              double x = 0;
              for (const auto &[p, q] : E[v])
                x -= at[p] * Kt[q][k];
              B[v * 54 + k] = B[k * 54 + v] = x;
            }
          for (unsigned int w = 9; w < 54; ++w)
            {
              double x = 0;
              for (const auto &[p, q] : E[w])
                for (const auto &[r, s] : E[v])
                  x += at[p] * Kt[q][r] * ht[s] + at[r] * Kt[s][p] * ht[q];
              B[v * 54 + w] = x;
            }
        }
    }

    // Adds sum_q c_q d^2 m_q / dx^2 of one segment's moments to hessian,
    // by reverse over forward mode in its 54 variables
    void
    add_segment_hessian(const std::vector<double>           &position,
                        const std::array<unsigned, n_v>     &index,
                        const std::array<double, n_moments> &c,
                        const TriangleRule                  &rule,
                        const EdgePoints                    &edge_points,
                        std::vector<double>                 &hessian)
    {
      using Inner        = Sacado::Fad::SFad<double, n_v>;
      using Number       = ReverseHessian::Number<Inner>;
      const unsigned n_x = position.size();
      ReverseHessian::start<Inner>();
      std::array<Number, n_v> inputs;
      Face<Number>            xs, xm;
      for (int v = 0; v < n_v; ++v)
        {
          inputs[v] = Number::independent(position[index[v]], v, n_v);
          (v < 27 ? xs[v / 3] : xm[(v - 27) / 3])[v % 3] = inputs[v];
        }
      std::array<Number, n_moments> m;
      if (!segment_moments<Number>(xs,
                                   xm,
                                   rule,
                                   edge_points,
                                   nullptr,
                                   nullptr,
                                   m))
        return;
      Number weighted = 0.;
      for (unsigned int q = 0; q < n_gap_moments; ++q)
        if (c[q] != 0)
          weighted += c[q] * m[q];
      if (weighted.index < 0)
        return;
      const ReverseHessian::Sweep<Inner> sweep(weighted);
      for (int v = 0; v < n_v; ++v)
        {
          const Inner adjoint = sweep(inputs[v]);
          for (int l = 0; l < adjoint.size(); ++l)
            hessian[index[v] * n_x + index[l]] += adjoint.dx(l);
        }
    }

    // The second derivatives of the normal force, sum_j lambda_j
    // d(w_j dh_j/dx_i)/dx_l: the segments' moments' own (reverse over
    // forward), then the normalized gaps' in the moments (a Fad of Fads in
    // the 54 they depend on) and the weights' first derivatives
    void
    add_exact_hessian(const FaceMoments                        &fm,
                      const Map9                               &T,
                      const std::array<double, 9>              &lambda,
                      const FaceValues<double>                 &f,
                      const std::vector<std::array<double, 9>> &dh,
                      const std::vector<std::array<double, 9>> &dw,
                      const std::vector<double>                &position,
                      const TriangleRule                       &rule,
                      std::vector<double>                      &hessian)
    {
      const unsigned int            n_x = position.size();
      std::array<double, 9>         c_node;
      std::array<double, n_moments> c;
      std::vector<double>           B;
      for (unsigned int j = 0; j < 9; ++j)
        c_node[j] = lambda[j] * f.weight[j];
      ratio_derivatives(fm.total, T, c_node, f.ratio, c, B);
      for (unsigned int k = 0; k < fm.variables.size(); ++k)
        add_segment_hessian(position,
                            fm.variables[k],
                            c,
                            rule,
                            fm.edge_points[k],
                            hessian);
      std::vector<double> BG(54 * n_x, 0.);
      for (unsigned int a = 0; a < 54; ++a)
        for (unsigned int b = 0; b < 54; ++b)
          if (const double h = B[a * 54 + b]; h != 0)
            for (unsigned int l = 0; l < n_x; ++l)
              BG[a * n_x + l] += h * fm.gradient[gap_variable(b) * n_x + l];
      for (unsigned int i = 0; i < n_x; ++i)
        for (unsigned int l = 0; l < n_x; ++l)
          {
            double h = 0;
            for (unsigned int a = 0; a < 54; ++a)
              h += fm.gradient[gap_variable(a) * n_x + i] * BG[a * n_x + l];
            for (unsigned int j = 0; j < 9; ++j)
              h += lambda[j] * dh[i][j] * dw[l][j];
            hessian[i * n_x + l] += h;
          }
    }

    void
    add_linearized(LinearizedValue                            &target,
                   const double                                value,
                   const std::vector<double>                  &derivative,
                   const std::vector<types::global_dof_index> &unknowns)
    {
      target.value += value;
      for (unsigned int i = 0; i < derivative.size(); ++i)
        if (derivative[i] != 0)
          target.derivatives[unknowns[i]] += derivative[i];
    }

    // The face's values and their gradients in the moments, chained to
    // the positions (dh, dw; direction = w dh), added to its nodes
    template <typename PairData>
    void
    add_face_values(PairData                                   &pair,
                    const unsigned int                          e,
                    const FaceMoments                          &fm,
                    const Map9                                 &T,
                    const std::vector<types::global_dof_index> &unknowns,
                    const bool                                  rates,
                    FaceValues<double>                         &f,
                    std::vector<std::array<double, 9>>         &dh,
                    std::vector<std::array<double, 9>>         &dw,
                    std::vector<std::array<double, 9>>         &direction)
    {
      const unsigned int n_x = dh.size();
      using AD               = Sacado::Fad::SFad<double, n_moments>;
      std::array<AD, n_moments> m;
      for (unsigned int q = 0; q < n_moments; ++q)
        m[q] = AD(n_moments, q, fm.total[q]);
      const auto g = face_values(m, T);
      for (unsigned int j = 0; j < 9; ++j)
        {
          f.ratio[j]  = g.ratio[j].val();
          f.weight[j] = g.weight[j].val();
          f.rate[j]   = g.rate[j].val();
          std::vector<double> d_gap(n_x), d_weight(n_x), d_rate(n_x);
          for (unsigned int i = 0; i < n_x; ++i)
            {
              double h = 0, w = 0, r = 0;
              for (unsigned int q = 0; q < n_moments; ++q)
                if (const double G = fm.gradient[q * n_x + i]; G != 0)
                  {
                    h += g.ratio[j].dx(q) * G;
                    w += g.weight[j].dx(q) * G;
                    r += g.rate[j].dx(q) * G;
                  }
              dh[i][j] = h, dw[i][j] = w;
              direction[i][j] = f.weight[j] * h;
              d_gap[i]        = f.weight[j] * h + f.ratio[j] * w;
              d_weight[i] = w, d_rate[i] = r;
            }
          if (T[j][j] == 0)
            continue;
          const unsigned int node = pair.secondary.face_nodes[e][j];
          add_linearized(pair.gap[node],
                         f.weight[j] * f.ratio[j],
                         d_gap,
                         unknowns);
          add_linearized(pair.weight[node], f.weight[j], d_weight, unknowns);
          if (rates)
            add_linearized(pair.gap_rate[node], f.rate[j], d_rate, unknowns);
        }
    }

  } // namespace



  template <>
  std::vector<types::global_dof_index>
  MortarContact<3>::quadratic_patch_unknowns(
    const PairData                  &pair,
    const unsigned int               e,
    const std::vector<unsigned int> &primary_faces) const
  {
    std::vector<types::global_dof_index> unknowns;
    for (const auto &[secondary, n] : patch_nodes_3d(pair, e, primary_faces))
      for (unsigned int d = 0; d < 3; ++d)
        unknowns.push_back(
          (secondary ? pair.secondary : pair.primary).dofs[n][d]);
    for (const unsigned int n : pair.secondary.face_nodes[e])
      unknowns.push_back(pair.secondary.dofs[n][3]);
    if (pair.friction_coefficient > 0)
      for (const unsigned int n : pair.secondary.face_nodes[e])
        for (const unsigned int c : {4, 5})
          unknowns.push_back(pair.secondary.dofs[n][c]);
    return unknowns;
  }



  template <>
  void
  MortarContact<3>::assemble_quadratic_patch(PairData          &pair,
                                             const unsigned int e,
                                             const TrialState  &state,
                                             PatchForces       &forces)
  {
    const auto nodes    = patch_nodes_3d(pair, e, pair.candidates[e]);
    const auto unknowns = quadratic_patch_unknowns(pair, e, pair.candidates[e]);
    const bool exact    = this->complementarity.exact_jacobian;
    const bool rates = this->complementarity.holds_contact() && state.dynamic;
    const bool friction = pair.friction_coefficient > 0;
    const TriangleRule &rule =
      ClippingGeometry::triangle_rule(std::min(quadrature_points + 1, 7u));
    const unsigned int  n_x = 3 * nodes.size();
    std::vector<double> position(n_x), velocity(n_x);
    for (unsigned int i = 0; i < n_x; ++i)
      {
        const auto &[secondary, n] = nodes[i / 3];
        const auto &surface        = secondary ? pair.secondary : pair.primary;
        position[i] = surface.reference[n][i % 3] + state.u(unknowns[i]);
        velocity[i] = state.v(unknowns[i]);
      }
    std::array<double, 9> lambda;
    for (unsigned int j = 0; j < 9; ++j)
      lambda[j] = state.u(unknowns[n_x + j]);

    const FaceMoments fm = face_moments(pair,
                                        e,
                                        nodes,
                                        position,
                                        velocity,
                                        state.c_v,
                                        rates,
                                        rule,
                                        segment_edge_points,
                                        friction);
    Face<double>      xs;
    for (unsigned int i = 0; i < 27; ++i)
      xs[i / 3][i % 3] = position[i];
    std::array<double, 9> covered;
    std::copy(fm.total.begin() + 9, fm.total.begin() + 18, covered.begin());
    // a sliver leaves the mass matrix nearly singular: nothing from it
    const Map9 T     = multiplier_map(xs, covered);
    double     whole = 0, covered_sum = 0;
    for (unsigned int j = 0; j < 9; ++j)
      covered_sum += covered[j];
    const QGauss<2> gauss(3);
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const auto s = shape(gauss.point(q)[0], gauss.point(q)[1]);
        whole += gauss.weight(q) *
                 norm(cross(combine(xs, s.dN[0]), combine(xs, s.dN[1])));
      }
    if (fm.covering.empty() || covered_sum < minimum_covered_fraction_2 * whole)
      return;

    FaceValues<double>                 f;
    std::vector<std::array<double, 9>> dh(n_x), dw(n_x), direction(n_x);
    add_face_values(pair, e, fm, T, unknowns, rates, f, dh, dw, direction);

    // 'approximate': the geometric stiffness (the derivatives of the
    // directions) is dropped
    std::vector<double> hessian(exact ? n_x * n_x : 0);
    if (exact && std::any_of(lambda.begin(), lambda.end(), [](double l) {
          return l != 0;
        }))
      add_exact_hessian(fm, T, lambda, f, dh, dw, position, rule, hessian);
    forces.add_normal_rows(unknowns,
                           lambda,
                           direction,
                           hessian,
                           [](unsigned int, auto &) {});
    if (!friction)
      return;

    std::vector<unsigned int>          secondary;
    std::vector<std::array<double, 2>> lambda_t(9);
    for (const auto &[on_secondary, n] : nodes)
      if (on_secondary)
        secondary.push_back(n);
    for (unsigned int j = 0; j < 9; ++j)
      for (unsigned int a = 0; a < 2; ++a)
        lambda_t[j][a] = state.u(unknowns[n_x + 9 + 2 * j + a]);
    add_friction(pair,
                 pair.secondary.face_nodes[e],
                 QuadraticSegment3D::friction_terms(pair.secondary,
                                                    e,
                                                    secondary,
                                                    fm,
                                                    T,
                                                    position,
                                                    velocity,
                                                    state.c_v,
                                                    lambda_t),
                 unknowns,
                 n_x,
                 forces);
  }
} // namespace ContactDynamics
