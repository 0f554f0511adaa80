// Meshing helpers of the built-in scenes.
//
// Every body is meshed on its own and the bodies are then put into one
// triangulation with a single create_triangulation() call, so that bodies
// never share vertices (GridGenerator::merge_triangulations() would glue
// coincident vertices together and the bodies could not separate).

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <contact_dynamics/scenes/body_mesh.h>

#include <algorithm>
#include <cmath>

namespace ContactDynamics
{
  namespace MeshSteps
  {
    unsigned int
    scaled(const double count, const double factor)
    {
      return static_cast<unsigned int>(
        std::max(1.0, std::round(count * factor)));
    }

    std::vector<double>
    uniform(const double length, const unsigned int n)
    {
      return std::vector<double>(n, length / n);
    }

    // r is found by bisection.
    std::vector<double>
    geometric(const double length, const double first, const unsigned int n)
    {
      if (n == 1 || first * n >= length)
        return uniform(length, n);

      const auto sum = [&](const double r) {
        double s = 0, h = first;
        for (unsigned int i = 0; i < n; ++i, h *= r)
          s += h;
        return s;
      };
      double lo = 1.0, hi = 2.0;
      while (sum(hi) < length)
        hi *= 2;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double mid              = 0.5 * (lo + hi);
          (sum(mid) < length ? lo : hi) = mid;
        }
      std::vector<double> steps(n);
      double              h = first;
      for (unsigned int i = 0; i < n; ++i, h *= lo)
        steps[i] = h;
      // Remove the bisection error so that the steps end exactly at length.
      const double total = sum(lo);
      for (double &s : steps)
        s *= length / total;
      return steps;
    }

    unsigned int
    n_growing(const double length, const double h, const double r)
    {
      return static_cast<unsigned int>(
        std::max(1.0,
                 std::ceil(std::log(1 + length * (r - 1) / h) / std::log(r))));
    }

    std::vector<double>
    reversed(std::vector<double> v)
    {
      std::reverse(v.begin(), v.end());
      return v;
    }

    std::vector<double>
    concatenate(std::vector<double> a, const std::vector<double> &b)
    {
      a.insert(a.end(), b.begin(), b.end());
      return a;
    }
  } // namespace MeshSteps

  namespace
  {
    // the lower and upper side of a box along each axis
    const char *const box_sides[3][2] = {{"left", "right"},
                                         {"bottom", "top"},
                                         {"front", "back"}};
  } // namespace

  std::vector<std::string>
  box_surface_names(const std::string &prefix, const unsigned int dim)
  {
    std::vector<std::string> names;
    for (unsigned int d = 0; d < dim; ++d)
      for (const char *side : box_sides[d])
        names.push_back(prefix + side);
    return names;
  }



  template <int dim>
  std::function<std::string(const Point<dim> &)>
  box_surfaces(const Point<dim>  &p0,
               const Point<dim>  &p1,
               const std::string &prefix)
  {
    const double tol = 1e-8 * p0.distance(p1);
    return [p0, p1, prefix, tol](const Point<dim> &c) -> std::string {
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (std::abs(c[d] - p0[d]) < tol)
            return prefix + box_sides[d][0];
          if (std::abs(c[d] - p1[d]) < tol)
            return prefix + box_sides[d][1];
        }
      return "";
    };
  }



  namespace
  {
    using namespace MeshSteps;

    // A scene whose Refinement factor asks for more cells than any machine
    // this code runs on can hold is refused before it allocates anything.
    void
    check_cell_count(const std::string &body, const double cells)
    {
      constexpr double max_cells = 1e7;
      AssertThrow(cells <= max_cells,
                  ExcMessage("The body '" + body + "' would have " +
                             std::to_string(static_cast<long long>(cells)) +
                             " cells, more than the " +
                             std::to_string(static_cast<long long>(max_cells)) +
                             " allowed per body. Lower Scene/Refinement "
                             "factor."));
    }

    BodyMesh<2>
    rectangle_mesh(const Point<2>            &p0,
                   const Point<2>            &p1,
                   const std::vector<double> &x_steps,
                   const std::vector<double> &y_steps,
                   const std::string         &prefix)
    {
      // Node coordinates; the last one is set exactly to avoid round-off.
      const auto nodes =
        [](const double a, const double b, const std::vector<double> &steps) {
          std::vector<double> x(1, a);
          for (const double s : steps)
            x.push_back(x.back() + s);
          x.back() = b;
          return x;
        };
      const std::vector<double> xs = nodes(p0[0], p1[0], x_steps);
      const std::vector<double> ys = nodes(p0[1], p1[1], y_steps);

      BodyMesh<2> body;
      for (const double y : ys)
        for (const double x : xs)
          body.vertices.emplace_back(x, y);
      const unsigned int nx = xs.size() - 1, ny = ys.size() - 1;
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            CellData<2> cell;
            cell.vertices[0] = j * (nx + 1) + i;
            cell.vertices[1] = j * (nx + 1) + i + 1;
            cell.vertices[2] = (j + 1) * (nx + 1) + i;
            cell.vertices[3] = (j + 1) * (nx + 1) + i + 1;
            body.cells.push_back(cell);
          }
      body.surface_of = box_surfaces<2>(p0, p1, prefix);
      return body;
    }


    // ----------------------------------------------------------------------
    // Multi-block structured mesh of a half-disc (arc downwards), optionally
    // with a rectangle on top of its diameter: the ironing tool and the Hertz
    // cylinder.
    //
    // Blocks: a square core [cx-a, cx+a] x [cy-a, cy] (a = R/2) under the
    // diameter, three blocks between the core and the arc (180-225, 225-315,
    // 315-360 degrees) and, for the tool, three blocks above the diameter
    // that match the nodes on y = cy. Every block is a Coons (transfinite)
    // block of its four edge curves, so that no cell has a degenerate
    // 180-degree corner.
    // ----------------------------------------------------------------------
    using Curve = std::function<Point<2>(const double)>;

    Curve
    segment(const Point<2> &a, const Point<2> &b)
    {
      return [a, b](const double s) {
        return Point<2>(a + s * (b - a));
      };
    }

    class TransfiniteMesher
    {
    public:
      explicit TransfiniteMesher(const double tolerance)
        : tolerance(tolerance)
      {}

      // Adds the ns x nt cells of the Coons (transfinite) block with the edges
      // bottom(s), top(s), left(t), right(t). (s, t) must be right-handed so
      // that the cells have positive measure.
      void
      add_block(const Curve       &bottom,
                const Curve       &top,
                const Curve       &left,
                const Curve       &right,
                const unsigned int ns,
                const unsigned int nt)
      {
        const Point<2> p00 = bottom(0), p10 = bottom(1), p01 = top(0),
                       p11 = top(1);
        std::vector<unsigned int> index((ns + 1) * (nt + 1));
        for (unsigned int j = 0; j <= nt; ++j)
          for (unsigned int i = 0; i <= ns; ++i)
            {
              const double s = 1.0 * i / ns, t = 1.0 * j / nt;
              // Edge nodes straight from the curves (exactly on the arc) and
              // merged with the nodes of neighbouring blocks.
              if (j == 0)
                index[j * (ns + 1) + i] = edge_vertex(bottom(s));
              else if (j == nt)
                index[j * (ns + 1) + i] = edge_vertex(top(s));
              else if (i == 0)
                index[j * (ns + 1) + i] = edge_vertex(left(t));
              else if (i == ns)
                index[j * (ns + 1) + i] = edge_vertex(right(t));
              else
                {
                  const Point<2> p((1 - t) * bottom(s) + t * top(s) +
                                   (1 - s) * left(t) + s * right(t) -
                                   ((1 - s) * (1 - t) * p00 +
                                    s * (1 - t) * p10 + (1 - s) * t * p01 +
                                    s * t * p11));
                  index[j * (ns + 1) + i] = body.vertices.size();
                  body.vertices.push_back(p);
                }
            }
        for (unsigned int j = 0; j < nt; ++j)
          for (unsigned int i = 0; i < ns; ++i)
            {
              CellData<2> cell;
              cell.vertices[0] = index[j * (ns + 1) + i];
              cell.vertices[1] = index[j * (ns + 1) + i + 1];
              cell.vertices[2] = index[(j + 1) * (ns + 1) + i];
              cell.vertices[3] = index[(j + 1) * (ns + 1) + i + 1];
              body.cells.push_back(cell);
            }
      }

      BodyMesh<2> body;

    private:
      unsigned int
      edge_vertex(const Point<2> &p)
      {
        // Only block edge nodes can coincide, so a linear search over them
        // is cheap.
        for (const unsigned int v : edge_vertices)
          if (body.vertices[v].distance(p) < tolerance)
            return v;
        edge_vertices.push_back(body.vertices.size());
        body.vertices.push_back(p);
        return body.vertices.size() - 1;
      }

      const double              tolerance;
      std::vector<unsigned int> edge_vertices;
    };

    struct HalfDiscNames
    {
      std::string arc;   // the circular arc
      std::string flat;  // the diameter (if no rectangle on top)
      std::string sides; // the vertical sides of the rectangle
      std::string top;   // the top of the rectangle
    };

    // n45: elements along 45 degrees of arc (90 degrees get 2*n45),
    // n_radial: elements between the core and the arc, rectangle_height > 0
    // puts a rectangle of width 2R on the diameter with n_up elements
    // vertically.
    BodyMesh<2>
    half_disc_mesh(const Point<2>      &center,
                   const double         R,
                   const unsigned int   n45,
                   const unsigned int   n_radial,
                   const double         rectangle_height,
                   const unsigned int   n_up,
                   const HalfDiscNames &names)
    {
      const double cx = center[0], cy = center[1], a = R / 2;
      const auto   arc_point = [=](const double theta) {
        // The diameter ends and the lowest point exactly, the rest on the
        // circle up to round-off.
        if (theta == numbers::PI)
          return Point<2>(cx - R, cy);
        if (theta == 1.5 * numbers::PI)
          return Point<2>(cx, cy - R);
        if (theta == 2 * numbers::PI)
          return Point<2>(cx + R, cy);
        return Point<2>(cx + R * std::cos(theta), cy + R * std::sin(theta));
      };
      const auto arc = [=](const double theta0, const double theta1) -> Curve {
        return [=](const double s) {
          return s == 0 ? arc_point(theta0) :
                 s == 1 ? arc_point(theta1) :
                          arc_point(theta0 + s * (theta1 - theta0));
        };
      };

      const double pi   = numbers::PI;
      const double t180 = pi, t225 = 1.25 * pi, t315 = 1.75 * pi, t360 = 2 * pi;

      // Corners of the core.
      const Point<2> c_ll(cx - a, cy - a), c_lr(cx + a, cy - a),
        c_ul(cx - a, cy), c_ur(cx + a, cy);

      TransfiniteMesher  mesher(1e-8 * R);
      const unsigned int n90 = 2 * n45;

      // Outer blocks: s runs along the arc with increasing angle, t from the
      // arc (t = 0) to the core (t = 1); this is right-handed.
      const auto outer = [&](const double       th0,
                             const double       th1,
                             const Point<2>    &q0,
                             const Point<2>    &q1,
                             const unsigned int ns) {
        mesher.add_block(arc(th0, th1),
                         segment(q0, q1),
                         segment(arc_point(th0), q0),
                         segment(arc_point(th1), q1),
                         ns,
                         n_radial);
      };
      outer(t180, t225, c_ul, c_ll, n45);
      outer(t225, t315, c_ll, c_lr, n90);
      outer(t315, t360, c_lr, c_ur, n45);

      // Core: s along x, t along y.
      mesher.add_block(segment(c_ll, c_lr),
                       segment(c_ul, c_ur),
                       segment(c_ll, c_ul),
                       segment(c_lr, c_ur),
                       n90,
                       n45);

      // Rectangle on top of the diameter, three blocks matching the nodes on
      // y = cy.
      if (rectangle_height > 0)
        {
          const double       xs[4] = {cx - R, cx - a, cx + a, cx + R};
          const unsigned int n[3]  = {n_radial, n90, n_radial};
          const double       y1    = cy + rectangle_height;
          for (unsigned int b = 0; b < 3; ++b)
            {
              const Point<2> p00(xs[b], cy), p10(xs[b + 1], cy), p01(xs[b], y1),
                p11(xs[b + 1], y1);
              mesher.add_block(segment(p00, p10),
                               segment(p01, p11),
                               segment(p00, p01),
                               segment(p10, p11),
                               n[b],
                               n_up);
            }
        }

      BodyMesh<2>  body  = std::move(mesher.body);
      const double tol   = 1e-8 * R;
      const double y_top = cy + rectangle_height;
      body.surface_of    = [=](const Point<2> &c) -> std::string {
        if (rectangle_height > 0 && std::abs(c[1] - y_top) < tol)
          return names.top;
        if (rectangle_height > 0 && c[1] > cy + tol)
          return names.sides;
        if (rectangle_height == 0 && std::abs(c[1] - cy) < tol)
          return names.flat;
        return names.arc;
      };
      body.curved_surface = names.arc;
      body.curve_center   = center;
      return body;
    }
  } // namespace



  BodyDefinition<2>
  rectangle_body(const std::string         &name,
                 const Point<2>            &p0,
                 const Point<2>            &p1,
                 const std::vector<double> &x_steps,
                 const std::vector<double> &y_steps)
  {
    check_cell_count(name, 1. * x_steps.size() * y_steps.size());
    return {name, box_surface_names(name + "_", 2), [=]() {
              return rectangle_mesh(p0, p1, x_steps, y_steps, name + "_");
            }};
  }



  BodyDefinition<2>
  rectangle_body(const std::string &name,
                 const Point<2>    &p0,
                 const Point<2>    &p1,
                 const unsigned int nx,
                 const unsigned int ny)
  {
    return rectangle_body(name,
                          p0,
                          p1,
                          uniform(p1[0] - p0[0], nx),
                          uniform(p1[1] - p0[1], ny));
  }



  BodyDefinition<2>
  half_disc_body(const std::string &name,
                 const Point<2>    &center,
                 const double       R,
                 const unsigned int n45,
                 const unsigned int n_radial,
                 const double       rectangle_height,
                 const unsigned int n_up)
  {
    const HalfDiscNames names =
      rectangle_height > 0 ?
        HalfDiscNames{name + "_arc", "", name + "_sides", name + "_top"} :
        HalfDiscNames{name + "_arc", name + "_top", "", ""};
    std::vector<std::string> surfaces;
    for (const std::string &surface :
         {names.arc, names.flat, names.sides, names.top})
      if (!surface.empty())
        surfaces.push_back(surface);
    return {name, surfaces, [=]() {
              return half_disc_mesh(center,
                                    R,
                                    n45,
                                    n_radial,
                                    rectangle_height,
                                    n_up,
                                    names);
            }};
  }



  template <int dim>
  SceneLayout
  layout_of(const std::vector<BodyDefinition<dim>> &bodies)
  {
    SceneLayout layout;
    for (const BodyDefinition<dim> &body : bodies)
      {
        layout.body_names.push_back(body.name);
        for (const std::string &surface : body.surfaces)
          {
            Assert(layout.surfaces.count(surface) == 0,
                   ExcInternalError("Two surfaces of a scene share a name."));
            const types::boundary_id id  = layout.surfaces.size();
            layout.surfaces[surface]     = id;
            layout.surface_body[surface] = layout.body_names.size() - 1;
          }
      }
    return layout;
  }



  // The vertex indices of every body are offset so that no vertex is shared.
  template <int dim>
  void
  mesh_bodies(const std::vector<BodyDefinition<dim>> &definitions,
              Triangulation<dim>                     &triangulation)
  {
    AssertThrow(
      triangulation.n_cells() == 0,
      ExcMessage(
        "Scene::create_triangulation() needs an empty triangulation."));
    const SceneLayout          layout = layout_of(definitions);
    std::vector<BodyMesh<dim>> bodies;
    for (const BodyDefinition<dim> &definition : definitions)
      bodies.push_back(definition.mesh());

    std::vector<Point<dim>>    vertices;
    std::vector<CellData<dim>> cells;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const unsigned int offset = vertices.size();
        vertices.insert(vertices.end(),
                        bodies[b].vertices.begin(),
                        bodies[b].vertices.end());
        for (CellData<dim> cell : bodies[b].cells)
          {
            for (unsigned int &v : cell.vertices)
              v += offset;
            cell.material_id = b;
            cells.push_back(cell);
          }
      }
    GridTools::consistently_order_cells(cells);
    triangulation.create_triangulation(vertices, cells, SubCellData());

    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const BodyMesh<dim> &body = bodies[cell->material_id()];
            const std::string    name = body.surface_of(face->center());
            Assert(!name.empty(),
                   ExcInternalError("A boundary face belongs to no surface."));
            face->set_boundary_id(layout.surface_id(name));
            // (in 3-D its edges too: they are refined first)
            if (!body.curved_surface.empty() && name == body.curved_surface)
              face->set_all_manifold_ids(1 + cell->material_id());
          }

    // Refinement keeps curved surfaces on their circles.
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (!bodies[b].curved_surface.empty())
        triangulation.set_manifold(1 + b,
                                   SphericalManifold<dim>(
                                     bodies[b].curve_center));
  }



  namespace
  {
    // the vertices and cells of a mesh of one box [p0, p1]
    template <int dim>
    BodyMesh<dim>
    box_mesh(const Triangulation<dim> &box,
             const Point<dim>         &p0,
             const Point<dim>         &p1,
             const std::string        &surface_prefix)
    {
      BodyMesh<dim> body;
      body.vertices = box.get_vertices();
      for (const auto &cell : box.active_cell_iterators())
        {
          CellData<dim> data;
          for (const unsigned int v : cell->vertex_indices())
            data.vertices[v] = cell->vertex_index(v);
          body.cells.push_back(data);
        }
      body.surface_of = box_surfaces<dim>(p0, p1, surface_prefix);
      return body;
    }
  } // namespace



  template <int dim>
  BodyDefinition<dim>
  box_body(const std::string                      &name,
           const Point<dim>                       &p0,
           const std::vector<std::vector<double>> &steps,
           const std::string                      &surface_prefix)
  {
    AssertThrow(steps.size() == dim, ExcInternalError());
    double cells = 1;
    for (const auto &s : steps)
      cells *= s.size();
    check_cell_count(name, cells);
    Point<dim> p1 = p0;
    for (unsigned int d = 0; d < dim; ++d)
      for (const double h : steps[d])
        p1[d] += h;
    return {name,
            box_surface_names(surface_prefix, dim),
            [p0, p1, steps, surface_prefix]() {
              Triangulation<dim> box;
              GridGenerator::subdivided_hyper_rectangle(box, steps, p0, p1);
              return box_mesh(box, p0, p1, surface_prefix);
            }};
  }



  template <int dim>
  BodyDefinition<dim>
  box_body(const std::string               &name,
           const Point<dim>                &p0,
           const Point<dim>                &p1,
           const std::vector<unsigned int> &n,
           const std::string               &surface_prefix)
  {
    double cells = 1;
    for (const unsigned int k : n)
      cells *= k;
    check_cell_count(name, cells);
    return {name,
            box_surface_names(surface_prefix, dim),
            [p0, p1, n, surface_prefix]() {
              Triangulation<dim> box;
              GridGenerator::subdivided_hyper_rectangle(box, n, p0, p1);
              return box_mesh(box, p0, p1, surface_prefix);
            }};
  }



  BodyDefinition<3>
  sphere_cap_body(const std::string                      &name,
                  const Point<3>                         &p0,
                  const std::vector<std::vector<double>> &steps,
                  const Point<3>                         &lowest,
                  const double                            radius)
  {
    BodyDefinition<3> body = box_body<3>(name, p0, steps, name + "_");
    const auto        box  = body.mesh;
    double            top  = p0[1];
    for (const double h : steps[1])
      top += h;
    body.mesh = [box, name, p0, top, lowest, radius]() {
      BodyMesh<3> m = box();
      for (auto &v : m.vertices)
        {
          const double r2 = (v[0] - lowest[0]) * (v[0] - lowest[0]) +
                            (v[2] - lowest[2]) * (v[2] - lowest[2]);
          AssertThrow(r2 < radius * radius,
                      ExcMessage("sphere_cap_body: the box is wider than the "
                                 "sphere"));
          const double bottom =
            lowest[1] + radius - std::sqrt(radius * radius - r2);
          AssertThrow(bottom < top,
                      ExcMessage("sphere_cap_body: the box is lower than the "
                                 "cap"));
          v[1] = bottom + (v[1] - p0[1]) / (top - p0[1]) * (top - bottom);
        }
      // refinement keeps the cap on the sphere
      m.curved_surface = name + "_bottom";
      m.curve_center   = lowest + Point<3>(0, radius, 0);
      // the sides and the top stay planes; the rest is the cap
      const auto planes = m.surface_of;
      m.surface_of      = [planes, name](const Point<3> &c) {
        const std::string surface = planes(c);
        return surface.empty() ? name + "_bottom" : surface;
      };
      return m;
    };
    return body;
  }



  template BodyDefinition<2>
  box_body(const std::string &,
           const Point<2> &,
           const Point<2> &,
           const std::vector<unsigned int> &,
           const std::string &);
  template BodyDefinition<3>
  box_body(const std::string &,
           const Point<3> &,
           const std::vector<std::vector<double>> &,
           const std::string &);
  template BodyDefinition<3>
  box_body(const std::string &,
           const Point<3> &,
           const Point<3> &,
           const std::vector<unsigned int> &,
           const std::string &);
  template SceneLayout
  layout_of(const std::vector<BodyDefinition<2>> &);
  template SceneLayout
  layout_of(const std::vector<BodyDefinition<3>> &);
  template void
  mesh_bodies(const std::vector<BodyDefinition<2>> &, Triangulation<2> &);
  template void
  mesh_bodies(const std::vector<BodyDefinition<3>> &, Triangulation<3> &);
  template std::function<std::string(const Point<2> &)>
  box_surfaces(const Point<2> &, const Point<2> &, const std::string &);
  template std::function<std::string(const Point<3> &)>
  box_surfaces(const Point<3> &, const Point<3> &, const std::string &);

  template <int dim>
  void
  BuiltInScene<dim>::parse_parameters(ParameterHandler &prm)
  {
    refinement_factor = prm.get_double("Refinement factor");
    parse_scene_parameters(prm);
  }

  template class BuiltInScene<2>;
  template class BuiltInScene<3>;
} // namespace ContactDynamics
