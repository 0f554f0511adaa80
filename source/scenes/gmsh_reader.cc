#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria_description.h>

#include <contact_dynamics/scenes/gmsh_reader.h>
#include <contact_dynamics/scenes/gmsh_second_order.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace ContactDynamics
{
  namespace GmshReader
  {
    namespace
    {
      struct PhysicalNames
      {
        // tag -> name, sorted by tag
        std::map<int, std::string> bodies;
        std::map<int, std::string> surfaces;
      };

      PhysicalNames
      read_physical_names(const std::string &file, const int dim)
      {
        AssertThrow(
          !file.empty(),
          ExcMessage(
            "The scene 'gmsh' needs a mesh file, but the parameter "
            "Scene/Mesh file is empty. Give the path of a .msh file."));
        std::ifstream in(file);
        AssertThrow(in,
                    ExcMessage("Cannot open the mesh file '" + file +
                               "' given as the parameter Scene/Mesh file."));

        PhysicalNames names;
        int           highest = -1; // the highest dimension of a group
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
                  AssertThrow(
                    words && first != std::string::npos && last > first,
                    ExcMessage(file_error(file) +
                               "has a malformed line in $PhysicalNames: '" +
                               line + "'."));
                  const std::string name =
                    line.substr(first + 1, last - first - 1);
                  highest = std::max(highest, d);
                  if (d == dim)
                    names.bodies[tag] = name;
                  else if (d == dim - 1)
                    names.surfaces[tag] = name;
                }
              break;
            }

        // a mesh of the other dimension would otherwise show as a scene
        // without surfaces (or bodies)
        AssertThrow(highest <= dim,
                    ExcMessage(file_error(file) + "is a " +
                               std::to_string(highest) +
                               "-D mesh (it has physical groups of dimension " +
                               std::to_string(highest) +
                               "), but Dimension = " + std::to_string(dim) +
                               ". Set Dimension = " + std::to_string(highest) +
                               " (at the top level of the parameter file) or "
                               "give a " +
                               std::to_string(dim) + "-D mesh."));
        AssertThrow(
          !names.bodies.empty(),
          ExcMessage(
            file_error(file) + "has no physical names of dimension " +
            std::to_string(dim) +
            (highest == dim - 1 && dim == 3 ?
               " (the highest is 2: if it is a 2-D mesh, set Dimension = 2)" :
               "") +
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
                        ExcMessage(file_error(file) + "names two bodies '" +
                                   name + "'; body names must be unique."));
            layout.body_names.push_back(name);
          }
        types::boundary_id id = 0;
        for (const auto &[tag, name] : names.surfaces)
          {
            AssertThrow(layout.surfaces.count(name) == 0,
                        ExcMessage(file_error(file) + "names two surfaces '" +
                                   name + "'; surface names must be unique."));
            layout.surfaces[name] = id++;
          }
        return layout;
      }

      // Reads the file (or its corner elements, if of second order) into a
      // scratch triangulation: material ids are the physical tags of the
      // cells, boundary ids those of the faces (0 if none).
      template <int dim>
      void
      read_tagged_mesh(const std::string          &file,
                       const SecondOrderFile<dim> &second_order,
                       Triangulation<dim>         &file_mesh)
      {
        GridIn<dim> grid_in;
        grid_in.attach_triangulation(file_mesh);
        std::ifstream      in(file);
        std::istringstream corners(second_order.corner_text);
        try
          {
            if (second_order.rewritten)
              grid_in.read_msh(corners);
            else
              grid_in.read_msh(in);
          }
        catch (const ExceptionBase &e)
          {
            std::ostringstream reason;
            e.print_info(reason);
            // the hint only where deal.II saw a tagged interior face
            const bool interior =
              reason.str().find("boundary id for an internal face") !=
              std::string::npos;
            AssertThrow(
              false,
              ExcMessage(
                file_error(file) +
                "could not be read by GridIn::read_msh():\n" + reason.str() +
                (interior ? "(A tagged line or face between two bodies "
                            "that share nodes: mesh touching bodies with "
                            "their own nodes and faces.)" :
                            "(GridIn reads Gmsh 2.2 or 4 ASCII files of "
                            "quadrilaterals or hexahedra, of second order "
                            "(9 or 27 nodes) in 2.2 and 4.1: another "
                            "element type, a number that does not parse, a "
                            "section shorter than its count or a cut file "
                            "stops it.)")));
          }
      }

      // A face by its sorted vertices (mapped through old_index if given).
      template <typename FaceIterator>
      std::vector<unsigned int>
      face_key(const FaceIterator              &face,
               const std::vector<unsigned int> &old_index)
      {
        std::vector<unsigned int> key;
        for (const unsigned int v : face->vertex_indices())
          key.push_back(old_index.empty() ? face->vertex_index(v) :
                                            old_index[face->vertex_index(v)]);
        std::sort(key.begin(), key.end());
        return key;
      }

      // Copies the cells into `triangulation` with the vertices copied once
      // per body, so that bodies meshed with common nodes still get separate
      // vertices; returns the file's index of every new vertex.
      template <int dim>
      std::vector<unsigned int>
      copy_bodies(const Triangulation<dim>                &file_mesh,
                  const std::map<int, types::material_id> &body_of_tag,
                  const std::string                       &file,
                  Triangulation<dim>                      &triangulation)
      {
        std::vector<Point<dim>>                                       vertices;
        std::vector<unsigned int>                                     old_index;
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> new_index;
        std::vector<CellData<dim>>                                    cells;
        for (const auto &cell : file_mesh.active_cell_iterators())
          {
            const auto body = body_of_tag.find(cell->material_id());
            AssertThrow(
              body != body_of_tag.end(),
              ExcMessage(file_error(file) + "has cells with the physical tag " +
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
        return old_index;
      }
    } // namespace



    SceneLayout
    read_layout(const std::string &file, const int dim)
    {
      return gmsh_layout(read_physical_names(file, dim), file);
    }



    template <int dim>
    std::shared_ptr<const QuadraticGeometry<dim>>
    read_mesh(const std::string  &file,
              const SceneLayout  &layout,
              Triangulation<dim> &triangulation)
    {
      AssertThrow(
        triangulation.n_cells() == 0,
        ExcMessage(
          "Scene::create_triangulation() needs an empty triangulation."));
      const PhysicalNames names = read_physical_names(file, dim);
      Triangulation<dim>  file_mesh;
      const auto          second_order = read_second_order<dim>(file);
      read_tagged_mesh(file, second_order, file_mesh);

      std::map<int, types::material_id> body_of_tag;
      for (const auto &[tag, name] : names.bodies)
        body_of_tag[tag] = layout.body_id(name);

      // Boundary faces of the file mesh, keyed by their sorted vertices.
      std::map<std::vector<unsigned int>, types::boundary_id> face_tag;
      for (const auto &cell : file_mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face_tag[face_key(face, {})] = face->boundary_id();

      const std::vector<unsigned int> old_index =
        copy_bodies(file_mesh, body_of_tag, file, triangulation);

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
                  file_error(file) + "has a boundary face at (" + where.str() +
                  ") of the body '" + layout.body_names[cell->material_id()] +
                  "' that is in no named physical group of dimension " +
                  std::to_string(dim - 1) +
                  ". Every boundary face must belong to a named surface "
                  "(bodies that touch need their own faces there)."));
              face->set_boundary_id(surface->second);
            }
      return cell_geometry(second_order, triangulation, file);
    }



    template std::shared_ptr<const QuadraticGeometry<2>>
    read_mesh(const std::string &, const SceneLayout &, Triangulation<2> &);
    template std::shared_ptr<const QuadraticGeometry<3>>
    read_mesh(const std::string &, const SceneLayout &, Triangulation<3> &);
  } // namespace GmshReader
} // namespace ContactDynamics
