// The quadrature points of a 3-D mortar segment and its integrals: what a
// pair of a secondary and a primary face contributes to the secondary
// face's mortar integrals (clipping_geometry.h).
#ifndef contact_dynamics_contact_segment_integrals_3d_h
#define contact_dynamics_contact_segment_integrals_3d_h

#include <contact_dynamics/contact/dual_basis_3d.h>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    /**
     * What a pair of a secondary and a primary face contributes to the
     * mortar integrals of the secondary face's nodes j (primary nodes k):
     * D_j = integral psi_j, M_jk = integral psi_j N_k (primary), and the
     * weighted gap g_j = integral psi_j (x_m - x_s) . n, over the part of
     * the secondary face the primary face covers.
     */
    template <typename Number>
    struct SegmentIntegrals
    {
      std::array<Number, 4>                D{}, gap{};
      std::array<std::array<Number, 4>, 4> M{};
      Number                               area = 0.;

      SegmentIntegrals()
      {
        D.fill(Number(0.));
        gap.fill(Number(0.));
        for (auto &row : M)
          row.fill(Number(0.));
      }
    };

    /**
     * A quadrature point of a mortar segment: its parameters on the
     * secondary and on the primary face, and its weight (area in the
     * auxiliary plane).
     */
    template <typename Number>
    struct SegmentPoint
    {
      Number xi_s, eta_s, xi_m, eta_m, weight;
    };

    /**
     * The quadrature points of the segment of a secondary face xs (nodal
     * unit normals ns) and a primary face xm, appended to `points`: the
     * auxiliary plane through the secondary face's center with its
     * interpolated normal there, both faces projected onto it along that
     * normal and clipped, the clip polygon triangulated, and at each point
     * of the 6-point rule on each triangle the points of both faces hit
     * along the plane's normal (Popp, Gee and Wall 2009: the integration
     * cells live in the plane; exact for flat secondary faces).
     * `tolerance` is relative to the secondary face's diameter. False if
     * the faces do not overlap; throws if a point of the overlap cannot be
     * projected onto its faces (then nothing is appended).
     */
    template <typename Number>
    bool
    segment_points(const std::array<Vec3<Number>, 4> &xs,
                   const std::array<Vec3<Number>, 4> &ns,
                   const std::array<Vec3<Number>, 4> &xm,
                   const double                       tolerance,
                   std::vector<SegmentPoint<Number>> &points,
                   const TriangleRule                &rule = triangle_rule())
    {
      const Number       half   = 0.5;
      const Vec3<Number> center = interpolate(xs, half, half);
      Vec3<Number>       normal = interpolate(ns, half, half);
      normal /= norm(normal);
      const Plane<Number> plane(center, normal);
      const double        diameter =
        std::max(value_of(norm(Vec3<Number>(xs[3] - xs[0]))),
                 value_of(norm(Vec3<Number>(xs[2] - xs[1]))));
      const Polygon<Number> clip = clip_polygon(project_face(plane, xm),
                                                project_face(plane, xs),
                                                tolerance * diameter);
      if (clip.empty())
        return false;
      const std::array<Vec3<double>, 4> xs_d = values(xs), xm_d = values(xm);
      const Vec3<double>                normal_d = values(normal);
      std::vector<SegmentPoint<Number>> found;
      for (const auto &triangle : triangulate(clip))
        {
          const Number area =
            signed_area(Polygon<Number>(triangle.begin(), triangle.end()));
          for (const auto &[b, w] : rule)
            {
              Point2<Number> q;
              for (unsigned int c = 0; c < 2; ++c)
                q[c] = b[0] * triangle[0][c] + b[1] * triangle[1][c] +
                       b[2] * triangle[2][c];
              const Vec3<Number> p = plane.point(q);
              double             s[3], m[3];
              // a point of the clip polygon lies on both projected faces:
              // not finding it on either is a geometry failure, not a
              // missing overlap
              AssertThrow(
                project_along_direction(xs_d,
                                        values(p),
                                        normal_d,
                                        s[0],
                                        s[1],
                                        s[2]) &&
                  project_along_direction(xm_d,
                                          values(p),
                                          normal_d,
                                          m[0],
                                          m[1],
                                          m[2]),
                dealii::ExcMessage(
                  "3-D mortar: a point of a mortar segment could not be "
                  "projected onto its faces (faces nearly parallel to the "
                  "auxiliary plane's normal, or badly distorted)."));
              const auto ps =
                projection_with_derivatives(xs, p, normal, s[0], s[1], s[2]);
              const auto pm =
                projection_with_derivatives(xm, p, normal, m[0], m[1], m[2]);
              found.push_back({ps[0], ps[1], pm[0], pm[1], Number(area * w)});
            }
        }
      points.insert(points.end(), found.begin(), found.end());
      return true;
    }

    /**
     * The gap (x_m - x_s) . n at a segment point, along the interpolated
     * unit normal n of the secondary face (returned in `normal`).
     */
    template <typename Number>
    Number
    point_gap(const std::array<Vec3<Number>, 4> &xs,
              const std::array<Vec3<Number>, 4> &ns,
              const std::array<Vec3<Number>, 4> &xm,
              const SegmentPoint<Number>        &q,
              Vec3<Number>                      &normal)
    {
      normal = interpolate(ns, q.xi_s, q.eta_s);
      normal /= norm(normal);
      return (interpolate(xm, q.xi_m, q.eta_m) -
              interpolate(xs, q.xi_s, q.eta_s)) *
             normal;
    }

    /**
     * The points of a face's segments as points of the face, for
     * dual_coefficients() of a partially covered face (the 2-D rule: the
     * dual basis is biorthogonal on what is integrated).
     */
    template <typename Number>
    std::vector<FacePoint<Number>>
    secondary_points(const std::vector<SegmentPoint<Number>> &points)
    {
      std::vector<FacePoint<Number>> result;
      for (const auto &q : points)
        result.push_back({q.xi_s, q.eta_s, q.weight});
      return result;
    }

    /**
     * Adds the mortar integrals at a segment's points: D_j, M_jk and the
     * weighted gap, the gap measured along the interpolated normal of the
     * secondary face.
     */
    template <typename Number>
    void
    add_segment_integrals(const std::array<Vec3<Number>, 4>          &xs,
                          const std::array<Vec3<Number>, 4>          &ns,
                          const std::array<Vec3<Number>, 4>          &xm,
                          const std::array<std::array<Number, 4>, 4> &dual,
                          const std::vector<SegmentPoint<Number>>    &points,
                          SegmentIntegrals<Number>                   &result)
    {
      for (const auto &q : points)
        {
          const auto   Ns = shape(q.xi_s, q.eta_s);
          const auto   Nm = shape(q.xi_m, q.eta_m);
          Vec3<Number> n;
          const Number g = point_gap(xs, ns, xm, q, n);
          result.area += q.weight;
          for (unsigned int j = 0; j < 4; ++j)
            {
              Number psi = 0.;
              for (unsigned int k = 0; k < 4; ++k)
                psi += dual[j][k] * Ns[k];
              result.D[j] += psi * q.weight;
              result.gap[j] += psi * g * q.weight;
              for (unsigned int k = 0; k < 4; ++k)
                result.M[j][k] += psi * Nm[k] * q.weight;
            }
        }
    }

    /**
     * segment_points() and add_segment_integrals() of one face pair with
     * given dual coefficients. False if the faces do not overlap.
     */
    template <typename Number>
    bool
    integrate_segment(const std::array<Vec3<Number>, 4>          &xs,
                      const std::array<Vec3<Number>, 4>          &ns,
                      const std::array<Vec3<Number>, 4>          &xm,
                      const std::array<std::array<Number, 4>, 4> &dual,
                      const double                                tolerance,
                      SegmentIntegrals<Number>                   &result)
    {
      std::vector<SegmentPoint<Number>> points;
      if (!segment_points(xs, ns, xm, tolerance, points))
        return false;
      add_segment_integrals(xs, ns, xm, dual, points, result);
      return true;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
