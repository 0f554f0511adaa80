#include <deal.II/base/exceptions.h>

#include <deal.II/grid/tria.h>

#include <contact_dynamics/parameters.h>
#include <contact_dynamics/scenes/scene.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    const SceneEntry *
    find_scene(const std::string &name)
    {
      for (const SceneEntry &entry : scene_registry())
        if (entry.name == name)
          return &entry;
      return nullptr;
    }

    // The Jacobian determinant of the (bi-, tri-)linear cell at vertex v:
    // the edges from v along each coordinate direction of the reference
    // cell, oriented from the lower to the upper face
    template <int dim>
    double
    corner_determinant(const typename Triangulation<dim>::cell_iterator &cell,
                       const unsigned int                                v)
    {
      Tensor<2, dim> J;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int lower = v & ~(1u << d), upper = v | (1u << d);
          for (unsigned int k = 0; k < dim; ++k)
            J[k][d] = cell->vertex(upper)[k] - cell->vertex(lower)[k];
        }
      return determinant(J);
    }

    // A coarse cell whose map is folded or flat at a corner (two vertices
    // coincide, a bow tie, a negative orientation) has no stiffness there:
    // the run would blame an inverted element later, or not at all.
    template <int dim>
    void
    check_cell_shapes(const Triangulation<dim> &triangulation,
                      const std::string        &scene)
    {
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        {
          AssertThrow(cell->reference_cell().is_hyper_cube(),
                      ExcMessage("Scene = " + scene + ": the cell at " +
                                 format_number(cell->center()[0]) + ", " +
                                 format_number(cell->center()[1]) + " is a " +
                                 cell->reference_cell().to_string() +
                                 ": only quadrilaterals (2-D) and hexahedra "
                                 "(3-D) are supported (Scene/Mesh file)."));
          for (const unsigned int v : cell->vertex_indices())
            {
              const double det  = corner_determinant<dim>(cell, v);
              const double size = std::pow(cell->diameter(), dim);
              if (det > 1e-10 * size)
                continue;
              std::ostringstream message;
              message << "Scene = " << scene << ": the cell with vertices";
              for (const unsigned int w : cell->vertex_indices())
                message << (w ? ", (" : " (") << cell->vertex(w) << ')';
              message << " is " << (det < 0 ? "inverted" : "degenerate")
                      << " at its vertex (" << cell->vertex(v)
                      << "): the Jacobian determinant there is " << det
                      << ", against " << size
                      << " for its size (diameter^dim). Two vertices "
                         "coincide, the cell is folded, its vertices are not "
                         "in Gmsh's order, or it is flatter than 1e-10; "
                         "correct the mesh (Scene/Mesh file) or the scene's "
                         "sizes.";
              AssertThrow(false, ExcMessage(message.str()));
            }
        }
    }

    // The documentation of Scene/Scene: every scene, where it exists and
    // what it is.
    std::string
    scene_documentation()
    {
      std::string text    = "The geometry: ";
      const auto &entries = scene_registry();
      for (unsigned int i = 0; i < entries.size(); ++i)
        text += (i == 0                 ? "" :
                 i + 1 < entries.size() ? "; " :
                                          "; or ") +
                ("'" + entries[i].name + "' (") +
                (entries[i].exists_in(3) ? "2-D and 3-D" : "2-D") + ", " +
                entries[i].description + ")";
      return text + ".";
    }
  } // namespace



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
                    ExcMessage(
                      "Unknown surface '" + name + "'. " +
                      (known.empty() ?
                         "The scene has no named surfaces." :
                         "The scene has the surfaces: " + join(known) + ".")));
      }
    return it->second;
  }



  template <int dim>
  void
  Scene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    {
      prm.declare_entry("Scene",
                        scene_registry().front().name,
                        Patterns::Selection(scene_names(2, "|")),
                        scene_documentation());
      prm.declare_entry(
        "Refinement factor",
        "1",
        Patterns::Double(0.05, 64),
        "Multiplies every element count of a built-in scene (each count "
        "becomes max(1, round(count*factor))). Not used for 'gmsh'.");
      for (const SceneEntry &entry : scene_registry())
        entry.declare_parameters(prm);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Scene<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    scene_name              = prm.get("Scene");
    const SceneEntry *entry = find_scene(scene_name);
    Assert(entry != nullptr, ExcInternalError());
    AssertThrow(entry->exists_in(dim),
                ExcMessage(
                  "The parameter Scene/Scene = '" + scene_name + "': scene '" +
                  scene_name +
                  "' is 2-D only, but Dimension = " + std::to_string(dim) +
                  "; in " + std::to_string(dim) + "-D use " +
                  scene_names(dim, "' or '").insert(0, "'") + "'."));
    scene = entry->create<dim>();
    scene->parse_parameters(prm);
    prm.leave_subsection();
  }



  template <int dim>
  const std::string &
  Scene<dim>::name() const
  {
    return scene_name;
  }



  template <int dim>
  SceneLayout
  Scene<dim>::layout() const
  {
    Assert(scene, ExcMessage("Scene::parse_parameters() was not called."));
    return scene->layout();
  }



  template <int dim>
  void
  Scene<dim>::create_triangulation(Triangulation<dim> &triangulation) const
  {
    Assert(scene, ExcMessage("Scene::parse_parameters() was not called."));
    scene->create_triangulation(triangulation);
    // (cells of second order: QuadraticGeometry checked the curved cells,
    // corners included; their chords may fold where the cells do not)
    if (!scene->cell_geometry())
      check_cell_shapes(triangulation, scene_name);
  }



  template <int dim>
  std::shared_ptr<const QuadraticGeometry<dim>>
  Scene<dim>::cell_geometry() const
  {
    Assert(scene, ExcMessage("Scene::parse_parameters() was not called."));
    return scene->cell_geometry();
  }



  template class Scene<2>;
  template class Scene<3>;
} // namespace ContactDynamics
