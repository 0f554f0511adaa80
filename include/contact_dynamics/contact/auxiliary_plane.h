// The auxiliary plane of a 3-D mortar segment (clipping_geometry.h): both
// faces projected onto it, the projected primary face clipped against the
// projected secondary face, and the clip polygon cut into triangles.
#ifndef contact_dynamics_contact_auxiliary_plane_h
#define contact_dynamics_contact_auxiliary_plane_h

#include <contact_dynamics/contact/face_geometry_3d.h>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    /**
     * The auxiliary plane of a secondary face: through `center`, with unit
     * normal `normal` and an orthonormal in-plane basis. The basis only
     * names coordinates: areas and the points mapped back do not depend on
     * it.
     */
    template <typename Number>
    struct Plane
    {
      Vec3<Number> center, normal, t1, t2;

      Plane(const Vec3<Number> &center, const Vec3<Number> &unit_normal)
        : center(center)
        , normal(unit_normal)
      {
        // the coordinate axis least aligned with the normal
        unsigned int axis = 0;
        for (unsigned int d = 1; d < 3; ++d)
          if (std::abs(value_of(normal[d])) < std::abs(value_of(normal[axis])))
            axis = d;
        Vec3<Number> e;
        e[axis]          = 1.;
        const Number e_n = e * normal;
        t1               = e - e_n * normal;
        t1 /= norm(t1);
        t2 = cross(normal, t1);
      }

      /** x projected along the normal, in plane coordinates. */
      Point2<Number>
      project(const Vec3<Number> &x) const
      {
        const Vec3<Number> d = x - center;
        return {{Number(d * t1), Number(d * t2)}};
      }

      /** The point of the plane with coordinates p. */
      Vec3<Number>
      point(const Point2<Number> &p) const
      {
        return center + p[0] * t1 + p[1] * t2;
      }
    };

    /** Signed area (positive counterclockwise), by the shoelace formula. */
    template <typename Number>
    Number
    signed_area(const Polygon<Number> &p)
    {
      Number area = 0.;
      for (unsigned int i = 0; i < p.size(); ++i)
        {
          const auto &a = p[i], &b = p[(i + 1) % p.size()];
          area += a[0] * b[1] - a[1] * b[0];
        }
      return area / 2.;
    }

    /**
     * The projected quadrilateral face, counterclockwise: its nodes in the
     * order 0, 1, 3, 2 (lexicographic to cyclic), reversed if they turn
     * clockwise as seen from the plane's normal.
     */
    template <typename Number>
    Polygon<Number>
    project_face(const Plane<Number>               &plane,
                 const std::array<Vec3<Number>, 4> &x)
    {
      Polygon<Number> p{plane.project(x[0]),
                        plane.project(x[1]),
                        plane.project(x[3]),
                        plane.project(x[2])};
      if (value_of(signed_area(p)) < 0)
        std::reverse(p.begin(), p.end());
      return p;
    }

    /**
     * The part of the polygon `subject` inside the convex counterclockwise
     * polygon `clip` (Sutherland-Hodgman, one clip edge at a time; the clip
     * polygon must be convex: the projection of a valid bilinear face onto
     * its own plane is, since a non-convex quadrilateral has a Jacobian
     * that changes sign). Edges of `clip` shorter than the tolerance are
     * skipped. A point
     * within `tolerance` (a length) of a clip edge counts as on it, and
     * points closer than `tolerance` merge: a shared edge, a vertex on an
     * edge and coincident vertices give no slivers or duplicate vertices.
     * Returns an empty polygon if fewer than 3 vertices remain.
     */
    template <typename Number>
    Polygon<Number>
    clip_polygon(const Polygon<Number> &subject,
                 const Polygon<Number> &clip,
                 const double           tolerance)
    {
      Polygon<Number> result = subject;
      for (unsigned int e = 0; e < clip.size() && result.size() > 0; ++e)
        {
          const Point2<Number> &c0 = clip[e], &c1 = clip[(e + 1) % clip.size()];
          const Number          ex = c1[0] - c0[0], ey = c1[1] - c0[1];
          using std::sqrt;
          const Number length = sqrt(ex * ex + ey * ey);
          // a degenerate edge bounds nothing (and its normal is undefined)
          if (value_of(length) <= tolerance)
            continue;
          // signed distance, positive inside (to the left of the edge)
          const auto distance = [&](const Point2<Number> &p) -> Number {
            return (ex * (p[1] - c0[1]) - ey * (p[0] - c0[0])) / length;
          };
          Polygon<Number>     input = std::move(result);
          std::vector<Number> d;
          for (const auto &p : input)
            d.push_back(distance(p));
          result.clear();
          for (unsigned int i = 0; i < input.size(); ++i)
            {
              const unsigned int j  = (i + 1) % input.size();
              const double       di = value_of(d[i]), dj = value_of(d[j]);
              if (di >= -tolerance)
                result.push_back(input[i]);
              // a crossing strictly from one side to the other
              if ((di > tolerance && dj < -tolerance) ||
                  (di < -tolerance && dj > tolerance))
                {
                  const Number s = d[i] / (d[i] - d[j]);
                  result.push_back(
                    {{input[i][0] + s * (input[j][0] - input[i][0]),
                      input[i][1] + s * (input[j][1] - input[i][1])}});
                }
            }
        }
      // merge points closer than the tolerance, cyclically
      Polygon<Number> merged;
      const auto close = [&](const Point2<Number> &a, const Point2<Number> &b) {
        const double dx = value_of(a[0]) - value_of(b[0]),
                     dy = value_of(a[1]) - value_of(b[1]);
        return dx * dx + dy * dy <= tolerance * tolerance;
      };
      for (const auto &p : result)
        if (merged.empty() || !close(merged.back(), p))
          merged.push_back(p);
      while (merged.size() > 1 && close(merged.front(), merged.back()))
        merged.pop_back();
      if (merged.size() < 3 ||
          std::abs(value_of(signed_area(merged))) <= tolerance * tolerance)
        return {};
      return merged;
    }

    /**
     * Triangles of a convex polygon: a fan around the mean of its vertices
     * (as in Popp et al. 2009: no triangle degenerates where the polygon
     * has collinear vertices); a triangle is returned as it is.
     */
    template <typename Number>
    std::vector<Triangle<Number>>
    triangulate(const Polygon<Number> &p)
    {
      std::vector<Triangle<Number>> triangles;
      if (p.size() < 3)
        return triangles;
      if (p.size() == 3)
        return {{{p[0], p[1], p[2]}}};
      Point2<Number> center{{0., 0.}};
      for (const auto &v : p)
        {
          center[0] += v[0] / double(p.size());
          center[1] += v[1] / double(p.size());
        }
      for (unsigned int i = 0; i < p.size(); ++i)
        triangles.push_back({{center, p[i], p[(i + 1) % p.size()]}});
      return triangles;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
