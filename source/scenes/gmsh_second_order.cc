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

      // The file as lines, with the section readers' position
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

        const std::string &
        at(const std::size_t i, const std::string &section) const
        {
          AssertThrow(i < text.size(),
                      ExcMessage(file_error(file) + "ends inside " + section +
                                 " (a cut file?)."));
          return text[i];
        }
      };

      // Rewrites one element (its type and node tags) to its corner
      // element, recording the nodes of a cell; refuses serendipity
      // elements.
      template <int dim>
      void
      rewrite_element(int                                 &type,
                      std::vector<long long>              &nodes,
                      std::vector<std::vector<long long>> &cells,
                      unsigned int                        &linear_cells,
                      const std::string                   &file)
      {
        AssertThrow(type != 16 && type != 17,
                    ExcMessage(file_error(file) +
                               "has serendipity elements (8-node "
                               "quadrilaterals or 20-node hexahedra): mesh "
                               "with Mesh.SecondOrderIncomplete = 0 (9-node "
                               "quadrilaterals, 27-node hexahedra) or with "
                               "elements of first order."));
        if (type == (dim == 2 ? 3 : 5))
          ++linear_cells;
        const auto second = second_order_types.find(type);
        if (second == second_order_types.end())
          return;
        AssertThrow(nodes.size() == second->second.n_nodes,
                    ExcMessage(file_error(file) + "has an element of type " +
                               std::to_string(type) + " with " +
                               std::to_string(nodes.size()) +
                               " nodes instead of " +
                               std::to_string(second->second.n_nodes) + "."));
        if (type == (dim == 2 ? 10 : 12))
          cells.push_back(nodes);
        type = second->second.corner_type;
        nodes.resize(second->second.n_corners);
      }

      // Rewrites the $Elements section in place (format 2.2 or 4.1);
      // returns whether an element was of second order.
      template <int dim>
      bool
      rewrite_elements(Lines                               &lines,
                       const bool                           v41,
                       std::vector<std::vector<long long>> &cells,
                       unsigned int                        &linear_cells)
      {
        const std::string section = "$Elements";
        std::size_t       i       = lines.find(section);
        if (i >= lines.text.size())
          return false;
        const auto  header  = numbers(lines.at(i++, section), lines.file);
        bool        changed = false;
        const auto &file    = lines.file;
        // one element "tag type n_tags tags... nodes..." (2.2) or
        // "tag nodes..." of a block of `type` (4.1)
        const auto element = [&](std::string &line, int &type) {
          std::vector<long long> w = numbers(line, file);
          const std::size_t n_head = v41 ? 1 : (w.size() > 2 ? 3 + w[2] : 0);
          AssertThrow(w.size() > n_head,
                      ExcMessage(file_error(file) +
                                 "has a malformed element '" + line +
                                 "' in $Elements."));
          if (!v41)
            type = w[1];
          std::vector<long long> nodes(w.begin() + n_head, w.end());
          const int              old_type = type;
          rewrite_element<dim>(type, nodes, cells, linear_cells, file);
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
              lines.at(i, section);
              element(lines.text[i++], type);
            }
        else
          for (long long b = 0; b < header[0]; ++b)
            {
              auto block = numbers(lines.at(i, section), file);
              AssertThrow(block.size() == 4,
                          ExcMessage(file_error(file) +
                                     "has a malformed block header '" +
                                     lines.text[i] + "' in $Elements."));
              const std::size_t header_line = i++;
              int               type        = block[2];
              for (long long e = 0; e < block[3]; ++e)
                {
                  int element_type = block[2];
                  lines.at(i, section);
                  element(lines.text[i++], element_type);
                  type = element_type;
                }
              if (type != block[2])
                lines.text[header_line] =
                  std::to_string(block[0]) + ' ' + std::to_string(block[1]) +
                  ' ' + std::to_string(type) + ' ' + std::to_string(block[3]);
            }
        return changed;
      }

      // The coordinates of every node by its tag ($Nodes, 2.2 or 4.1)
      template <int dim>
      std::unordered_map<long long, Point<dim>>
      read_nodes(const Lines &lines, const bool v41)
      {
        const std::string section = "$Nodes";
        std::size_t       i       = lines.find(section);
        const auto        header  = numbers(lines.at(i++, section), lines.file);
        std::unordered_map<long long, Point<dim>> nodes;
        const auto read_point = [&](const std::string &line, Point<dim> &p) {
          std::istringstream words(line);
          for (unsigned int d = 0; d < dim; ++d)
            words >> p[d];
          AssertThrow(words,
                      ExcMessage(file_error(lines.file) +
                                 "has a malformed node '" + line +
                                 "' in $Nodes."));
        };
        if (!v41)
          for (long long n = 0; n < header[0]; ++n, ++i)
            {
              const std::string &line = lines.at(i, section);
              const std::size_t  cut  = line.find_first_of(" \t");
              const long long tag = numbers(line.substr(0, cut), lines.file)[0];
              read_point(line.substr(cut), nodes[tag]);
            }
        else
          for (long long b = 0; b < header[0]; ++b)
            {
              const auto block = numbers(lines.at(i++, section), lines.file);
              AssertThrow(block.size() == 4,
                          ExcMessage(file_error(lines.file) +
                                     "has a malformed block header in "
                                     "$Nodes."));
              std::vector<long long> tags;
              for (long long n = 0; n < block[3]; ++n)
                tags.push_back(numbers(lines.at(i++, section), lines.file)[0]);
              for (const long long tag : tags)
                read_point(lines.at(i++, section), nodes[tag]);
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
        lines.text.push_back(line);
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

      std::vector<std::vector<long long>> cells;
      unsigned int                        linear_cells = 0;
      result.second_order =
        rewrite_elements<dim>(lines, v41, cells, linear_cells);
      if (!result.second_order)
        return result;
      AssertThrow(cells.empty() || linear_cells == 0,
                  ExcMessage(file_error(file) + "mixes " +
                             std::to_string(cells.size()) +
                             " cells of second order with " +
                             std::to_string(linear_cells) +
                             " of first order: mesh all cells with the same "
                             "order."));
      const auto nodes = read_nodes<dim>(lines, v41);
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
          const auto found = cell_of.find(key(points));
          AssertThrow(found != cell_of.end(), ExcInternalError());
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
            AssertThrow(e != entities.end(), ExcInternalError());
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
