#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/scenes/gmsh_second_order.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace ContactDynamics
{
  namespace GmshReader
  {
    namespace
    {
      // Gmsh's types of second order: the corner element's type, the
      // nodes and the corners
      struct SecondOrderType
      {
        int          corner_type;
        unsigned int n_nodes;
        unsigned int n_corners;
      };
      const std::map<int, SecondOrderType> second_order_types = {
        {8, {1, 3, 2}},   // 3-node line
        {10, {3, 9, 4}},  // 9-node quadrilateral
        {12, {5, 27, 8}}, // 27-node hexahedron
      };

      // Gmsh's order of the nodes after the corners: the edges' and (3-D)
      // the faces' by their corners (Gmsh manual, "Node ordering")
      const std::vector<std::vector<unsigned int>> quad9_entities = {{0, 1},
                                                                     {1, 2},
                                                                     {2, 3},
                                                                     {0, 3}};
      const std::vector<std::vector<unsigned int>> hex27_entities = {
        {0, 1},
        {0, 3},
        {0, 4},
        {1, 2},
        {1, 5},
        {2, 3},
        {2, 6},
        {3, 7},
        {4, 5},
        {4, 7},
        {5, 6},
        {6, 7},
        {0, 1, 2, 3},
        {0, 1, 4, 5},
        {0, 3, 4, 7},
        {1, 2, 5, 6},
        {2, 3, 6, 7},
        {4, 5, 6, 7}};

      std::vector<long long>
      numbers(const std::string &line, const std::string &file)
      {
        std::istringstream     words(line);
        std::vector<long long> result;
        for (long long n; words >> n;)
          result.push_back(n);
        AssertThrow(words.eof() && !result.empty(),
                    ExcMessage(file_error(file) + "has a malformed line '" +
                               line + "' where integers were expected."));
        return result;
      }

      // The file as lines (without '\r'), read section by section
      struct Lines
      {
        std::vector<std::string> text;
        std::string              file;

        std::size_t
        find(const std::string &section) const
        {
          for (std::size_t i = 0; i < text.size(); ++i)
            if (Utilities::trim(text[i]) == section)
              return i + 1;
          return text.size();
        }

        // The index of the next line of `section` with content from i on
        // (i moves past it); a section's end or the file's end there means
        // the section is shorter than its counts.
        std::size_t
        next(std::size_t &i, const std::string &section) const
        {
          while (i < text.size() && Utilities::trim(text[i]).empty())
            ++i;
          AssertThrow(i < text.size() && text[i].find('$') == std::string::npos,
                      ExcMessage(file_error(file) + "ends its " + section +
                                 " section before the count its header "
                                 "gives (a cut file, or a wrong count)."));
          return i++;
        }
      };

      // Rewrites one element (its type and node tags) to its corner
      // element, recording the nodes of a cell; refuses the elements of
      // second order it cannot read. `seen`: whether the file is of second
      // order at all.
      template <int dim>
      void
      rewrite_element(int                                 &type,
                      std::vector<long long>              &nodes,
                      std::vector<std::vector<long long>> &cells,
                      unsigned int                        &other_cells,
                      bool                                &seen,
                      const std::string                   &file)
      {
        const bool serendipity = type == 16 || type == 17;
        const bool simplex     = type == 9 || type == 11;
        seen =
          seen || serendipity || simplex || second_order_types.count(type) > 0;
        AssertThrow(!serendipity,
                    ExcMessage(file_error(file) +
                               "has serendipity elements (8-node "
                               "quadrilaterals or 20-node hexahedra): mesh "
                               "with Mesh.SecondOrderIncomplete = 0 (9-node "
                               "quadrilaterals, 27-node hexahedra) or with "
                               "elements of first order."));
        AssertThrow(!simplex,
                    ExcMessage(file_error(file) +
                               "has triangles or tetrahedra of second order: "
                               "only quadrilaterals and hexahedra are read "
                               "(Mesh.RecombineAll = 1, and "
                               "Mesh.SubdivisionAlgorithm = 1 or 2 for "
                               "meshes of quadrilaterals or hexahedra "
                               "only)."));
        // cells of first order, triangles, tetrahedra, prisms, pyramids
        if (dim == 2 ? (type == 2 || type == 3) : (type >= 4 && type <= 7))
          ++other_cells;
        const auto second = second_order_types.find(type);
        if (second == second_order_types.end())
          return;
        AssertThrow(nodes.size() == second->second.n_nodes,
                    ExcMessage(file_error(file) + "has an element of type " +
                               std::to_string(type) + " with " +
                               std::to_string(nodes.size()) +
                               " nodes instead of " +
                               std::to_string(second->second.n_nodes) +
                               " (a cut line?)."));
        if (type == (dim == 2 ? 10 : 12))
          cells.push_back(nodes);
        type = second->second.corner_type;
        nodes.resize(second->second.n_corners);
      }

      // Rewrites the $Elements section in place (format 2.2 or 4.1);
      // returns whether an element was rewritten.
      template <int dim>
      bool
      rewrite_elements(Lines                               &lines,
                       const bool                           v41,
                       std::vector<std::vector<long long>> &cells,
                       unsigned int                        &other_cells,
                       bool                                &seen)
      {
        const std::string section = "$Elements";
        std::size_t       i       = lines.find(section);
        if (i >= lines.text.size())
          return false;
        const auto &file    = lines.file;
        const auto  header  = numbers(lines.text[lines.next(i, section)], file);
        bool        changed = false;
        // one element "tag type n_tags tags... nodes..." (2.2) or
        // "tag nodes..." of a block of `type` (4.1)
        const auto element = [&](std::string &line, int &type) {
          std::vector<long long> w = numbers(line, file);
          AssertThrow(v41 ? w.size() >= 2 :
                            w.size() >= 4 && w[2] >= 0 &&
                              w.size() > 3 + std::size_t(w[2]),
                      ExcMessage(file_error(file) +
                                 "has a malformed element '" + line +
                                 "' in $Elements."));
          const std::size_t n_head = v41 ? 1 : 3 + w[2];
          if (!v41)
            type = w[1];
          std::vector<long long> nodes(w.begin() + n_head, w.end());
          const int              old_type = type;
          rewrite_element<dim>(type, nodes, cells, other_cells, seen, file);
          if (type == old_type)
            return;
          changed = true;
          std::ostringstream out;
          for (std::size_t k = 0; k < n_head; ++k)
            out << (k == 1 && !v41 ? type : w[k]) << ' ';
          for (const long long n : nodes)
            out << n << ' ';
          line = out.str();
        };
        if (!v41)
          for (long long e = 0; e < header[0]; ++e)
            {
              int type = 0;
              element(lines.text[lines.next(i, section)], type);
            }
        else
          for (long long b = 0; b < header[0]; ++b)
            {
              const std::size_t header_line = lines.next(i, section);
              const auto        block = numbers(lines.text[header_line], file);
              AssertThrow(
                block.size() == 4,
                ExcMessage(file_error(file) + "has a malformed block header '" +
                           lines.text[header_line] + "' in $Elements."));
              int type = block[2];
              for (long long e = 0; e < block[3]; ++e)
                {
                  int element_type = block[2];
                  element(lines.text[lines.next(i, section)], element_type);
                  type = element_type;
                }
              if (type != block[2])
                lines.text[header_line] =
                  std::to_string(block[0]) + ' ' + std::to_string(block[1]) +
                  ' ' + std::to_string(type) + ' ' + std::to_string(block[3]);
            }
        return changed;
      }

      // The coordinates of every node by its tag ($Nodes, 2.2 or 4.1). The
      // parametric coordinates of a 4.1 file (Mesh.SaveParametric), which
      // GridIn does not read, are cut off; `changed` says so.
      template <int dim>
      std::unordered_map<long long, Point<dim>>
      read_nodes(Lines &lines, const bool v41, bool &changed)
      {
        const std::string section = "$Nodes";
        std::size_t       i       = lines.find(section);
        AssertThrow(i < lines.text.size(),
                    ExcMessage(file_error(lines.file) +
                               "has no $Nodes section (a $ParametricNodes "
                               "section is not read: save without "
                               "Mesh.SaveParametric)."));
        const auto header =
          numbers(lines.text[lines.next(i, section)], lines.file);
        std::unordered_map<long long, Point<dim>> nodes;
        // "tag x y z" (2.2) or "x y z" (4.1)
        const auto read_point = [&](const std::string &line) {
          std::istringstream words(line);
          long long          tag = 0;
          if (!v41)
            words >> tag;
          Point<dim> p;
          double     z = 0;
          for (unsigned int d = 0; d < dim; ++d)
            words >> p[d];
          if (dim == 2)
            words >> z;
          AssertThrow(words,
                      ExcMessage(file_error(lines.file) +
                                 "has a malformed node '" + line +
                                 "' in $Nodes."));
          return std::make_pair(tag, p);
        };
        if (!v41)
          for (long long n = 0; n < header[0]; ++n)
            nodes.insert(read_point(lines.text[lines.next(i, section)]));
        else
          for (long long b = 0; b < header[0]; ++b)
            {
              const std::size_t header_line = lines.next(i, section);
              const auto block = numbers(lines.text[header_line], lines.file);
              AssertThrow(block.size() == 4,
                          ExcMessage(file_error(lines.file) +
                                     "has a malformed block header '" +
                                     lines.text[header_line] + "' in $Nodes."));
              std::vector<long long> tags;
              for (long long n = 0; n < block[3]; ++n)
                tags.push_back(
                  numbers(lines.text[lines.next(i, section)], lines.file)[0]);
              for (const long long tag : tags)
                {
                  std::string &line = lines.text[lines.next(i, section)];
                  nodes[tag]        = read_point(line).second;
                  if (block[2] != 0) // x y z only
                    {
                      std::istringstream xyz(line);
                      std::string        x, y, z;
                      xyz >> x >> y >> z;
                      line = x + ' ' + y + ' ' + z;
                    }
                }
              if (block[2] != 0)
                {
                  lines.text[header_line] = std::to_string(block[0]) + ' ' +
                                            std::to_string(block[1]) + " 0 " +
                                            std::to_string(block[3]);
                  changed = true;
                }
            }
        return nodes;
      }
    } // namespace



    std::string
    file_error(const std::string &file)
    {
      return "The mesh file '" + file + "' (parameter Scene/Mesh file) ";
    }



    template <int dim>
    SecondOrderFile<dim>
    read_second_order(const std::string &file)
    {
      SecondOrderFile<dim> result;
      Lines                lines;
      lines.file = file;
      std::ifstream in(file);
      for (std::string line; std::getline(in, line);)
        {
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          lines.text.push_back(line);
        }
      const std::size_t format = lines.find("$MeshFormat");
      if (format >= lines.text.size())
        return result;
      std::istringstream words(lines.text[format]);
      double             version   = 0;
      int                file_type = -1;
      words >> version >> file_type;
      const bool v22 = std::abs(version - 2.2) < 1e-8;
      const bool v41 = std::abs(version - 4.1) < 1e-8;
      if (!(v22 || v41) || file_type != 0)
        return result;

      std::vector<std::vector<long long>>       cells;
      unsigned int                              other_cells = 0;
      bool                                      seen = false, changed = false;
      std::unordered_map<long long, Point<dim>> nodes;
      try
        {
          result.second_order =
            rewrite_elements<dim>(lines, v41, cells, other_cells, seen);
          if (result.second_order || v41)
            nodes = read_nodes<dim>(lines, v41, changed);
        }
      catch (const ExceptionBase &)
        {
          // a file of first order: GridIn reads it and words its errors
          if (!seen)
            return SecondOrderFile<dim>();
          throw;
        }
      AssertThrow(cells.empty() || other_cells == 0,
                  ExcMessage(file_error(file) + "mixes " +
                             std::to_string(cells.size()) +
                             " cells of second order with " +
                             std::to_string(other_cells) +
                             " of first order (or triangles, tetrahedra): "
                             "mesh all cells as quadrilaterals or "
                             "hexahedra of the same order."));
      for (const auto &cell : cells)
        {
          result.cell_nodes.emplace_back();
          for (const long long tag : cell)
            {
              const auto node = nodes.find(tag);
              AssertThrow(node != nodes.end(),
                          ExcMessage(
                            file_error(file) + "has a cell with the node " +
                            std::to_string(tag) + " that is not in $Nodes."));
              result.cell_nodes.back().push_back(node->second);
            }
        }
      result.rewritten = result.second_order || changed;
      if (!result.rewritten)
        return result;
      for (const std::string &line : lines.text)
        result.corner_text += line + '\n';
      return result;
    }



    template <int dim>
    std::shared_ptr<const QuadraticGeometry<dim>>
    cell_geometry(const SecondOrderFile<dim> &file_nodes,
                  const Triangulation<dim>   &triangulation,
                  const std::string          &file)
    {
      if (file_nodes.cell_nodes.empty())
        return nullptr;
      constexpr unsigned int n_corners = GeometryInfo<dim>::vertices_per_cell;
      // a cell is known by its corners' coordinates, sorted
      const auto key = [](std::vector<Point<dim>> corners) {
        std::sort(corners.begin(),
                  corners.end(),
                  [](const Point<dim> &a, const Point<dim> &b) {
                    return std::lexicographical_compare(a.begin_raw(),
                                                        a.end_raw(),
                                                        b.begin_raw(),
                                                        b.end_raw());
                  });
        std::vector<double> k;
        for (const auto &p : corners)
          k.insert(k.end(), p.begin_raw(), p.end_raw());
        return k;
      };
      std::map<std::vector<double>, unsigned int> cell_of;
      for (unsigned int c = 0; c < file_nodes.cell_nodes.size(); ++c)
        {
          const auto &g = file_nodes.cell_nodes[c];
          cell_of[key({g.begin(), g.begin() + n_corners})] = c;
        }
      const auto &entities = dim == 2 ? quad9_entities : hex27_entities;

      std::vector<std::vector<Point<dim>>> nodes(triangulation.n_cells(0));
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        {
          std::vector<Point<dim>> points;
          for (const unsigned int v : cell->vertex_indices())
            points.push_back(cell->vertex(v));
          const auto         found = cell_of.find(key(points));
          std::ostringstream where;
          where << cell->vertex(0);
          // (a cell with two corners at one point is found, but not its
          // edges)
          const std::string degenerate =
            file_error(file) + "has a cell of second order with the corner (" +
            where.str() +
            ") whose edges cannot be told apart: two of its corners "
            "coincide. Mesh it anew.";
          AssertThrow(found != cell_of.end(), ExcMessage(degenerate));
          const auto &g = file_nodes.cell_nodes[found->second];
          // the file's corner at each vertex
          std::array<unsigned int, n_corners> corner;
          for (const unsigned int v : cell->vertex_indices())
            corner[v] = std::find(g.begin(), g.begin() + n_corners, points[v]) -
                        g.begin();
          // the file's node of the entity with these vertices
          const auto node = [&](std::vector<unsigned int> vertices) {
            for (unsigned int &v : vertices)
              v = corner[v];
            std::sort(vertices.begin(), vertices.end());
            const auto e =
              std::find(entities.begin(), entities.end(), vertices);
            AssertThrow(e != entities.end(), ExcMessage(degenerate));
            return g[n_corners + (e - entities.begin())];
          };
          for (const unsigned int l : cell->line_indices())
            points.push_back(
              node({GeometryInfo<dim>::line_to_cell_vertices(l, 0),
                    GeometryInfo<dim>::line_to_cell_vertices(l, 1)}));
          if (dim == 3)
            for (const unsigned int f : cell->face_indices())
              {
                std::vector<unsigned int> vertices;
                for (unsigned int i = 0; i < 4; ++i)
                  vertices.push_back(
                    GeometryInfo<dim>::face_to_cell_vertices(f, i));
                points.push_back(node(vertices));
              }
          points.push_back(g.back());
          nodes[cell->index()] = std::move(points);
        }
      return std::make_shared<const QuadraticGeometry<dim>>(std::move(nodes),
                                                            file_error(file));
    }



    template SecondOrderFile<2>
    read_second_order(const std::string &);
    template SecondOrderFile<3>
    read_second_order(const std::string &);
    template std::shared_ptr<const QuadraticGeometry<2>>
    cell_geometry(const SecondOrderFile<2> &,
                  const Triangulation<2> &,
                  const std::string &);
    template std::shared_ptr<const QuadraticGeometry<3>>
    cell_geometry(const SecondOrderFile<3> &,
                  const Triangulation<3> &,
                  const std::string &);
  } // namespace GmshReader
} // namespace ContactDynamics
