// The geometry of a simulation: built-in parametric scenes and Gmsh files.
//
// Every body is meshed on its own and the bodies are then put into one
// triangulation with a single create_triangulation() call, so that bodies
// never share vertices (GridGenerator::merge_triangulations() would glue
// coincident vertices together and the bodies could not separate).

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <contact_dynamics/scenes/scene.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace ContactDynamics
{
  using namespace dealii;

  namespace
  {
    // ----------------------------------------------------------------------
    // Small helpers
    // ----------------------------------------------------------------------

    std::string
    join(const std::vector<std::string> &names)
    {
      std::string result;
      for (const auto &name : names)
        result += (result.empty() ? "" : ", ") + name;
      return result;
    }

    // The number of elements of a built-in scene at a given refinement factor.
    unsigned int
    scaled(const double count, const double factor)
    {
      return static_cast<unsigned int>(
        std::max(1.0, std::round(count * factor)));
    }

    std::vector<double>
    uniform_steps(const double length, const unsigned int n)
    {
      return std::vector<double>(n, length / n);
    }

    // n steps first*r^i (i = 0..n-1) that add up to length; r >= 1 is found
    // by bisection. Falls back to uniform steps if the first step is already
    // too long for a growing sequence.
    std::vector<double>
    geometric_steps(const double       length,
                    const double       first,
                    const unsigned int n)
    {
      if (n == 1 || first * n >= length)
        return uniform_steps(length, n);

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

    // Number of geometrically growing steps (ratio r) that start at size h
    // and cover the given length.
    unsigned int
    n_growing_steps(const double length, const double h, const double r)
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

    // ----------------------------------------------------------------------
    // One body: its own vertices and cells, and which named surface a
    // boundary face belongs to (decided by the face centre).
    // ----------------------------------------------------------------------
    template <int dim>
    struct BodyMesh
    {
      std::vector<Point<dim>>                        vertices;
      std::vector<CellData<dim>>                     cells;
      std::function<std::string(const Point<dim> &)> surface_of;

      // A surface on a circle (cylinder) that gets a SphericalManifold.
      std::string curved_surface;
      Point<dim>  curve_center;
    };

    // Surfaces of an axis-parallel box: prefix + left/right/bottom/top
    // (/front/back in 3-D).
    template <int dim>
    std::function<std::string(const Point<dim> &)>
    box_surfaces(const Point<dim>  &p0,
                 const Point<dim>  &p1,
                 const std::string &prefix)
    {
      const double tol = 1e-8 * p0.distance(p1);
      return [p0, p1, prefix, tol](const Point<dim> &c) -> std::string {
        static const char *lower[3] = {"left", "bottom", "front"};
        static const char *upper[3] = {"right", "top", "back"};
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (std::abs(c[d] - p0[d]) < tol)
              return prefix + lower[d];
            if (std::abs(c[d] - p1[d]) < tol)
              return prefix + upper[d];
          }
        return "";
      };
    }

    // A 2-D rectangle [p0, p1] on the tensor grid given by the step sizes.
    BodyMesh<2>
    rectangle_body(const Point<2>            &p0,
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

    BodyMesh<2>
    rectangle_body(const Point<2>    &p0,
                   const Point<2>    &p1,
                   const unsigned int nx,
                   const unsigned int ny,
                   const std::string &prefix)
    {
      return rectangle_body(p0,
                            p1,
                            uniform_steps(p1[0] - p0[0], nx),
                            uniform_steps(p1[1] - p0[1], ny),
                            prefix);
    }

    // ----------------------------------------------------------------------
    // Multi-block structured mesh of a half-disc (arc downwards), optionally
    // with a rectangle on top of its diameter: the ironing tool and the Hertz
    // cylinder.
    //
    // Blocks: a square core [cx-a, cx+a] x [cy-a, cy] (a = R/2) under the
    // diameter, three blocks between the core and the arc (180-225, 225-315,
    // 315-360 degrees) and, for the tool, three blocks above the diameter
    // that match the nodes on y = cy. Every block is a Coons patch of its
    // four edge curves, so that no cell has a degenerate 180-degree corner.
    // ----------------------------------------------------------------------
    using Curve = std::function<Point<2>(const double)>;

    Curve
    segment(const Point<2> &a, const Point<2> &b)
    {
      return [a, b](const double s) {
        return Point<2>(a + s * (b - a));
      };
    }

    class PatchMesher
    {
    public:
      explicit PatchMesher(const double tolerance)
        : tolerance(tolerance)
      {}

      // Adds the ns x nt cells of the Coons patch with the edges bottom(s),
      // top(s), left(t), right(t). (s, t) must be right-handed so that the
      // cells have positive measure.
      void
      add_patch(const Curve       &bottom,
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
              // merged with the nodes of neighbouring patches.
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
        // Only patch edge nodes can coincide, so a linear search over them
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
    half_disc_body(const Point<2>      &center,
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

      PatchMesher        mesher(1e-8 * R);
      const unsigned int n90 = 2 * n45;

      // Outer blocks: s runs along the arc with increasing angle, t from the
      // arc (t = 0) to the core (t = 1); this is right-handed.
      const auto outer = [&](const double       th0,
                             const double       th1,
                             const Point<2>    &q0,
                             const Point<2>    &q1,
                             const unsigned int ns) {
        mesher.add_patch(arc(th0, th1),
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
      mesher.add_patch(segment(c_ll, c_lr),
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
              mesher.add_patch(segment(p00, p10),
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

    // ----------------------------------------------------------------------
    // Puts the bodies into one triangulation: body i gets material id i, the
    // vertex indices of every body are offset so that no vertex is shared.
    // ----------------------------------------------------------------------
    template <int dim>
    void
    assemble(const std::vector<BodyMesh<dim>> &bodies,
             const SceneLayout                &layout,
             Triangulation<dim>               &triangulation)
    {
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
                     ExcInternalError(
                       "A boundary face belongs to no surface."));
              face->set_boundary_id(layout.surface_id(name));
              if (!body.curved_surface.empty() && name == body.curved_surface)
                face->set_manifold_id(1 + cell->material_id());
            }

      // Refinement keeps curved surfaces on their circles.
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (!bodies[b].curved_surface.empty())
          triangulation.set_manifold(1 + b,
                                     SphericalManifold<dim>(
                                       bodies[b].curve_center));
    }

    // ----------------------------------------------------------------------
    // Gmsh physical names
    // ----------------------------------------------------------------------
    struct PhysicalNames
    {
      // tag -> name, sorted by tag
      std::map<int, std::string> bodies;
      std::map<int, std::string> surfaces;
    };

    std::string
    mesh_file_error_prefix(const std::string &file)
    {
      return "The mesh file '" + file + "' (parameter Scene/Mesh file) ";
    }

    PhysicalNames
    read_physical_names(const std::string &file, const int dim)
    {
      AssertThrow(!file.empty(),
                  ExcMessage(
                    "The scene 'gmsh' needs a mesh file, but the parameter "
                    "Scene/Mesh file is empty. Give the path of a .msh file."));
      std::ifstream in(file);
      AssertThrow(in,
                  ExcMessage("Cannot open the mesh file '" + file +
                             "' given as the parameter Scene/Mesh file."));

      PhysicalNames names;
      std::string   line;
      while (std::getline(in, line))
        if (Utilities::trim(line) == "$PhysicalNames")
          {
            std::getline(in, line);
            const unsigned int n =
              Utilities::string_to_int(Utilities::trim(line));
            for (unsigned int i = 0; i < n && std::getline(in, line); ++i)
              {
                std::istringstream words(line);
                int                d = -1, tag = -1;
                words >> d >> tag;
                const auto first = line.find('"'), last = line.rfind('"');
                AssertThrow(words && first != std::string::npos && last > first,
                            ExcMessage(
                              mesh_file_error_prefix(file) +
                              "has a malformed line in $PhysicalNames: '" +
                              line + "'."));
                const std::string name =
                  line.substr(first + 1, last - first - 1);
                if (d == dim)
                  names.bodies[tag] = name;
                else if (d == dim - 1)
                  names.surfaces[tag] = name;
              }
            break;
          }

      AssertThrow(
        !names.bodies.empty(),
        ExcMessage(
          mesh_file_error_prefix(file) + "has no physical names of dimension " +
          std::to_string(dim) +
          ". Name the bodies with physical groups of the cells (Physical " +
          (dim == 2 ? "Surface" : "Volume") + " in Gmsh)."));
      return names;
    }

    SceneLayout
    gmsh_layout(const PhysicalNames &names, const std::string &file)
    {
      SceneLayout layout;
      for (const auto &[tag, name] : names.bodies)
        {
          AssertThrow(std::find(layout.body_names.begin(),
                                layout.body_names.end(),
                                name) == layout.body_names.end(),
                      ExcMessage(mesh_file_error_prefix(file) +
                                 "names two bodies '" + name +
                                 "'; body names must be unique."));
          layout.body_names.push_back(name);
        }
      types::boundary_id id = 0;
      for (const auto &[tag, name] : names.surfaces)
        {
          AssertThrow(layout.surfaces.count(name) == 0,
                      ExcMessage(mesh_file_error_prefix(file) +
                                 "names two surfaces '" + name +
                                 "'; surface names must be unique."));
          layout.surfaces[name] = id++;
        }
      return layout;
    }

    // Builds the layout from a list of names: body i -> material id i,
    // surface k -> boundary id k.
    SceneLayout
    make_layout(const std::vector<std::string> &bodies,
                const std::vector<std::string> &surfaces)
    {
      SceneLayout layout;
      layout.body_names = bodies;
      for (unsigned int i = 0; i < surfaces.size(); ++i)
        layout.surfaces[surfaces[i]] = i;
      return layout;
    }

    std::vector<std::string>
    box_surface_names(const std::string &prefix, const unsigned int dim)
    {
      std::vector<std::string> names;
      for (const char *side :
           {"left", "right", "bottom", "top", "front", "back"})
        if (names.size() < 2 * dim)
          names.push_back(prefix + side);
      return names;
    }
  } // namespace



  // ------------------------------------------------------------------------
  // SceneLayout
  // ------------------------------------------------------------------------
  types::material_id
  SceneLayout::body_id(const std::string &name) const
  {
    const auto it = std::find(body_names.begin(), body_names.end(), name);
    AssertThrow(it != body_names.end(),
                ExcMessage("Unknown body '" + name +
                           "'. The scene has the bodies: " + join(body_names) +
                           "."));
    return it - body_names.begin();
  }



  types::boundary_id
  SceneLayout::surface_id(const std::string &name) const
  {
    const auto it = surfaces.find(name);
    if (it == surfaces.end())
      {
        std::vector<std::string> known;
        for (const auto &surface : surfaces)
          known.push_back(surface.first);
        AssertThrow(false,
                    ExcMessage("Unknown surface '" + name +
                               "'. The scene has the surfaces: " + join(known) +
                               "."));
      }
    return it->second;
  }



  // ------------------------------------------------------------------------
  // Parameters
  // ------------------------------------------------------------------------
  template <int dim>
  void
  Scene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    {
      prm.declare_entry(
        "Scene",
        "bouncing block",
        Patterns::Selection(
          "bouncing block|ironing|patch test|hertz|bar impact|block|gmsh"),
        "The geometry. The built-in scenes 'bouncing block', 'ironing', "
        "'patch test', 'hertz' and 'bar impact' are 2-D; 'block' (one box, "
        "see subsection Block) and 'gmsh' (read from Mesh file) work in 2-D "
        "and 3-D.");
      prm.declare_entry(
        "Refinement factor",
        "1",
        Patterns::Double(0.05, 64),
        "Multiplies every element count of a built-in scene (each count "
        "becomes max(1, round(count*factor))). Not used for 'gmsh'.");
      prm.declare_entry(
        "Mesh file",
        "",
        Patterns::Anything(),
        "Gmsh .msh file (format 2.2 or 4, ASCII) for the scene 'gmsh'. "
        "Physical groups of the cells are the bodies (numbered in the order "
        "of their tags), physical groups of the boundary faces are the "
        "surfaces; all of them need a name in $PhysicalNames.");

      prm.enter_subsection("Block");
      {
        prm.declare_entry(
          "Origin",
          "0, 0",
          Patterns::List(Patterns::Double(), 2, 3),
          "Lower left (front) corner of the box, one coordinate per "
          "space dimension.");
        prm.declare_entry(
          "Size",
          "1, 1",
          Patterns::List(Patterns::Double(1e-12), 2, 3),
          "Edge lengths of the box, one per space dimension. The body is "
          "called 'body', its surfaces left, right, bottom, top (and front "
          "= z min, back = z max in 3-D).");
        prm.declare_entry(
          "Subdivisions",
          "4, 4",
          Patterns::List(Patterns::Integer(1), 2, 3),
          "Number of elements along each edge of the box, one per space "
          "dimension.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Hertz");
      {
        prm.declare_entry(
          "Radius",
          "1",
          Patterns::Double(1e-12),
          "Radius of the half-cylinder (flat face on top, arc at the "
          "bottom) pressed onto the block.");
        prm.declare_entry(
          "Block width",
          "8",
          Patterns::Double(1e-12),
          "Width of the block [-width/2, width/2] x [0, height].");
        prm.declare_entry("Block height",
                          "4",
                          Patterns::Double(1e-12),
                          "Height of the block.");
        prm.declare_entry(
          "Gap",
          "0",
          Patterns::Double(0),
          "Initial vertical distance between the lowest point of the "
          "cylinder and the top of the block.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Bar impact");
      {
        prm.declare_entry(
          "Bar length",
          "1",
          Patterns::Double(1e-12),
          "Length L of the striker [-gap-L, -gap] x [0, height].");
        prm.declare_entry("Bar height",
                          "0.1",
                          Patterns::Double(1e-12),
                          "Height of the bars.");
        prm.declare_entry(
          "Gap",
          "0.01",
          Patterns::Double(0),
          "Initial distance between the striker and the target (at x = 0).");
        prm.declare_entry(
          "Target",
          "wall",
          Patterns::Selection("wall|bar"),
          "'wall': a short block [0, 0.2 L] x [0, height] (make it stiff and "
          "fix its right side); 'bar': a second bar [0, Target length] x "
          "[0, height].");
        prm.declare_entry("Target length",
                          "1",
                          Patterns::Double(1e-12),
                          "Length of the target bar (Target = bar).");
        prm.declare_entry(
          "Elements along bar",
          "40",
          Patterns::Integer(1),
          "Elements along the striker; the height and the target get "
          "elements of the same size.");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Scene<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    {
      scene_name        = prm.get("Scene");
      refinement_factor = prm.get_double("Refinement factor");
      mesh_file         = prm.get("Mesh file");

      prm.enter_subsection("Block");
      {
        // The patterns allow 2 or 3 entries; the space dimension decides.
        const auto list = [&](const std::string &entry) {
          const std::string              value = prm.get(entry);
          const std::vector<std::string> items =
            Utilities::split_string_list(value);
          AssertThrow(
            scene_name != "block" || items.size() == dim,
            ExcMessage("The parameter Scene/Block/" + entry + " = '" + value +
                       "' has " + std::to_string(items.size()) +
                       " entries, but the problem is " + std::to_string(dim) +
                       "-D: give exactly " + std::to_string(dim) + " values."));
          return items;
        };
        block_origin = Utilities::string_to_double(list("Origin"));
        block_size   = Utilities::string_to_double(list("Size"));
        block_subdivisions.clear();
        for (const int n : Utilities::string_to_int(list("Subdivisions")))
          block_subdivisions.push_back(n);
      }
      prm.leave_subsection();

      prm.enter_subsection("Hertz");
      {
        hertz_radius       = prm.get_double("Radius");
        hertz_block_width  = prm.get_double("Block width");
        hertz_block_height = prm.get_double("Block height");
        hertz_gap          = prm.get_double("Gap");
      }
      prm.leave_subsection();

      prm.enter_subsection("Bar impact");
      {
        bar_length        = prm.get_double("Bar length");
        bar_height        = prm.get_double("Bar height");
        bar_gap           = prm.get_double("Gap");
        bar_target        = prm.get("Target");
        bar_target_length = prm.get_double("Target length");
        bar_elements      = prm.get_integer("Elements along bar");
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();

    AssertThrow(dim == 2 || scene_name == "block" || scene_name == "gmsh",
                ExcMessage("The parameter Scene/Scene = '" + scene_name +
                           "': scene '" + scene_name +
                           "' is 2-D only; in 3-D use 'block' or 'gmsh'."));

    // Report a missing or unnamed mesh file now rather than at mesh time.
    if (scene_name == "gmsh")
      read_physical_names(mesh_file, dim);
  }



  template <int dim>
  const std::string &
  Scene<dim>::name() const
  {
    return scene_name;
  }



  // ------------------------------------------------------------------------
  // Layout
  // ------------------------------------------------------------------------
  template <int dim>
  SceneLayout
  Scene<dim>::layout() const
  {
    AssertThrow(dim == 2 || scene_name == "block" || scene_name == "gmsh",
                ExcMessage("scene '" + scene_name + "' is 2-D only"));

    if (scene_name == "bouncing block")
      return make_layout({"block", "substrate"},
                         {"block_bottom",
                          "block_top",
                          "block_left",
                          "block_right",
                          "substrate_top",
                          "substrate_bottom",
                          "substrate_left",
                          "substrate_right"});
    else if (scene_name == "ironing")
      return make_layout({"tool", "substrate"},
                         {"tool_arc",
                          "tool_sides",
                          "tool_top",
                          "substrate_top",
                          "substrate_bottom",
                          "substrate_left",
                          "substrate_right"});
    else if (scene_name == "patch test")
      return make_layout({"upper", "lower"},
                         {"upper_top",
                          "upper_bottom",
                          "upper_left",
                          "upper_right",
                          "lower_top",
                          "lower_bottom",
                          "lower_left",
                          "lower_right"});
    else if (scene_name == "hertz")
      return make_layout({"cylinder", "block"},
                         {"cylinder_arc",
                          "cylinder_top",
                          "block_top",
                          "block_bottom",
                          "block_left",
                          "block_right"});
    else if (scene_name == "bar impact")
      {
        std::vector<std::string> surfaces;
        for (const std::string body : {"striker", "target"})
          for (const char *side : {"left", "right", "top", "bottom"})
            surfaces.push_back(body + "_" + side);
        return make_layout({"striker", "target"}, surfaces);
      }
    else if (scene_name == "block")
      return make_layout({"body"}, box_surface_names("", dim));
    else if (scene_name == "gmsh")
      return gmsh_layout(read_physical_names(mesh_file, dim), mesh_file);

    AssertThrow(false, ExcMessage("Unknown scene '" + scene_name + "'."));
    return {};
  }



  // ------------------------------------------------------------------------
  // Meshes
  // ------------------------------------------------------------------------
  template <int dim>
  void
  Scene<dim>::create_triangulation(Triangulation<dim> &triangulation) const
  {
    AssertThrow(
      triangulation.n_cells() == 0,
      ExcMessage(
        "Scene::create_triangulation() needs an empty triangulation."));
    const SceneLayout layout = this->layout(); // also rejects 2-D scenes in 3-D
    const double      f      = refinement_factor;

    if (scene_name == "block")
      {
        Point<dim>                p0, p1;
        std::vector<unsigned int> subdivisions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p0[d]           = block_origin[d];
            p1[d]           = block_origin[d] + block_size[d];
            subdivisions[d] = scaled(block_subdivisions[d], f);
          }
        Triangulation<dim> box;
        GridGenerator::subdivided_hyper_rectangle(box, subdivisions, p0, p1);

        BodyMesh<dim> body;
        body.vertices = box.get_vertices();
        for (const auto &cell : box.active_cell_iterators())
          {
            CellData<dim> data;
            for (const unsigned int v : cell->vertex_indices())
              data.vertices[v] = cell->vertex_index(v);
            body.cells.push_back(data);
          }
        body.surface_of = box_surfaces<dim>(p0, p1, "");
        assemble<dim>({body}, layout, triangulation);
        return;
      }

    if (scene_name == "gmsh")
      {
        // Read into a scratch triangulation: material ids are the physical
        // tags of the cells, boundary ids those of the faces (0 if none).
        const PhysicalNames names = read_physical_names(mesh_file, dim);
        Triangulation<dim>  file_mesh;
        {
          GridIn<dim> grid_in;
          grid_in.attach_triangulation(file_mesh);
          std::ifstream in(mesh_file);
          try
            {
              grid_in.read_msh(in);
            }
          catch (const ExceptionBase &e)
            {
              std::ostringstream reason;
              e.print_info(reason);
              AssertThrow(false,
                          ExcMessage(
                            mesh_file_error_prefix(mesh_file) +
                            "could not be read by GridIn::read_msh():\n" +
                            reason.str() +
                            "(A common cause: a tagged line between two bodies "
                            "that share nodes. Mesh touching bodies with their "
                            "own nodes and faces.)"));
            }
        }

        std::map<int, types::material_id> body_of_tag;
        for (const auto &[tag, name] : names.bodies)
          body_of_tag[tag] = layout.body_id(name);

        // Boundary faces of the file mesh, keyed by their sorted vertices.
        std::map<std::vector<unsigned int>, types::boundary_id> face_tag;
        const auto face_key = [](const auto                      &face,
                                 const std::vector<unsigned int> &old_index) {
          std::vector<unsigned int> key;
          for (const unsigned int v : face->vertex_indices())
            key.push_back(old_index.empty() ? face->vertex_index(v) :
                                              old_index[face->vertex_index(v)]);
          std::sort(key.begin(), key.end());
          return key;
        };
        for (const auto &cell : file_mesh.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              face_tag[face_key(face, {})] = face->boundary_id();

        // Copy the vertices once per body, so that bodies meshed with
        // common nodes still get separate vertices.
        std::vector<Point<dim>>                                       vertices;
        std::vector<unsigned int>                                     old_index;
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> new_index;
        std::vector<CellData<dim>>                                    cells;
        for (const auto &cell : file_mesh.active_cell_iterators())
          {
            const auto body = body_of_tag.find(cell->material_id());
            AssertThrow(
              body != body_of_tag.end(),
              ExcMessage(mesh_file_error_prefix(mesh_file) +
                         "has cells with the physical tag " +
                         std::to_string(cell->material_id()) +
                         " that has no name in $PhysicalNames; every cell must "
                         "belong to a named body."));
            CellData<dim> data(cell->n_vertices());
            for (const unsigned int v : cell->vertex_indices())
              {
                const auto key =
                  std::make_pair(body->second, cell->vertex_index(v));
                auto it = new_index.find(key);
                if (it == new_index.end())
                  {
                    it = new_index.emplace(key, vertices.size()).first;
                    vertices.push_back(cell->vertex(v));
                    old_index.push_back(cell->vertex_index(v));
                  }
                data.vertices[v] = it->second;
              }
            data.material_id = body->second;
            cells.push_back(data);
          }
        triangulation.create_triangulation(vertices, cells, SubCellData());

        std::map<int, types::boundary_id> surface_of_tag;
        for (const auto &[tag, name] : names.surfaces)
          surface_of_tag[tag] = layout.surface_id(name);
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const auto tag = face_tag.find(face_key(face, old_index));
                const auto surface =
                  (tag == face_tag.end() ? surface_of_tag.end() :
                                           surface_of_tag.find(tag->second));
                std::ostringstream where;
                where << face->center();
                AssertThrow(
                  surface != surface_of_tag.end(),
                  ExcMessage(
                    mesh_file_error_prefix(mesh_file) +
                    "has a boundary face at (" + where.str() +
                    ") of the body '" + layout.body_names[cell->material_id()] +
                    "' that is in no named physical group of dimension " +
                    std::to_string(dim - 1) +
                    ". Every boundary face must belong to a named surface "
                    "(bodies that touch need their own faces there)."));
                face->set_boundary_id(surface->second);
              }
        return;
      }

    // The built-in 2-D scenes.
    if constexpr (dim == 2)
      {
        std::vector<BodyMesh<2>> bodies;
        if (scene_name == "bouncing block")
          {
            bodies.push_back(rectangle_body(Point<2>(-2, 0),
                                            Point<2>(-1, 1),
                                            scaled(10, f),
                                            scaled(10, f),
                                            "block_"));
            bodies.push_back(rectangle_body(Point<2>(-2.5, -1),
                                            Point<2>(2.5, 0),
                                            scaled(49, f),
                                            scaled(10, f),
                                            "substrate_"));
          }
        else if (scene_name == "ironing")
          {
            bodies.push_back(
              half_disc_body(Point<2>(1.2, 5.02),
                             1.0,
                             scaled(16, f),
                             scaled(12, f),
                             1.0,
                             scaled(16, f),
                             {"tool_arc", "", "tool_sides", "tool_top"}));
            // 200 elements along the top; vertically a geometric progression
            // from the top element length down to coarser cells.
            const unsigned int nx = scaled(200, f);
            bodies.push_back(rectangle_body(
              Point<2>(0, 0),
              Point<2>(12, 4),
              uniform_steps(12, nx),
              reversed(geometric_steps(4, 12.0 / nx, scaled(30, f))),
              "substrate_"));
          }
        else if (scene_name == "patch test")
          {
            bodies.push_back(rectangle_body(Point<2>(0, 0.5),
                                            Point<2>(1, 1),
                                            scaled(7, f),
                                            scaled(4, f),
                                            "upper_"));
            bodies.push_back(rectangle_body(Point<2>(0, 0),
                                            Point<2>(1, 0.5),
                                            scaled(5, f),
                                            scaled(3, f),
                                            "lower_"));
          }
        else if (scene_name == "hertz")
          {
            const double R = hertz_radius, w = hertz_block_width,
                         h = hertz_block_height;
            bodies.push_back(
              half_disc_body(Point<2>(0, h + hertz_gap + R),
                             R,
                             scaled(32, f),
                             scaled(20, f),
                             0,
                             0,
                             {"cylinder_arc", "cylinder_top", "", ""}));

            // Block: uniform cells of size R/40 within a distance R of the
            // top centre, geometrically growing (ratio about 1.1) outside.
            const double size   = R / scaled(40, f);
            const auto   graded = [&](const double fine_length,
                                    const double total) {
              // Steps from the contact point outwards.
              const double fine = std::min(fine_length, total);
              if (total - fine <= 2 * R / 40)
                return uniform_steps(total, scaled(total / (R / 40), f));
              const unsigned int n_fine =
                std::max(1u, (unsigned int)std::round(fine / size));
              const unsigned int n_grow =
                scaled(n_growing_steps(total - fine, R / 40, 1.1), f);
              return concatenate(uniform_steps(fine, n_fine),
                                 geometric_steps(total - fine,
                                                 fine / n_fine,
                                                 n_grow));
            };
            const std::vector<double> half_x = graded(R, w / 2);
            bodies.push_back(
              rectangle_body(Point<2>(-w / 2, 0),
                             Point<2>(w / 2, h),
                             concatenate(reversed(half_x), half_x),
                             reversed(graded(R, h)),
                             "block_"));
          }
        else if (scene_name == "bar impact")
          {
            const double       L = bar_length, h = bar_height, gap = bar_gap;
            const unsigned int nx = scaled(bar_elements, f);
            const unsigned int ny = scaled(nx * h / L, 1);
            const double       target_length =
              (bar_target == "bar" ? bar_target_length : 0.2 * L);
            bodies.push_back(rectangle_body(Point<2>(-gap - L, 0),
                                            Point<2>(-gap, h),
                                            nx,
                                            ny,
                                            "striker_"));
            bodies.push_back(rectangle_body(Point<2>(0, 0),
                                            Point<2>(target_length, h),
                                            scaled(nx * target_length / L, 1),
                                            ny,
                                            "target_"));
          }
        else
          AssertThrow(false, ExcMessage("Unknown scene '" + scene_name + "'."));

        assemble<2>(bodies, layout, triangulation);
      }
    else
      AssertThrow(false, ExcMessage("scene '" + scene_name + "' is 2-D only"));
  }



  template class Scene<2>;
  template class Scene<3>;
} // namespace ContactDynamics
