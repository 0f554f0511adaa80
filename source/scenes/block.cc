// One box, in 2-D or 3-D (subsection Block).
#include <deal.II/base/utilities.h>

#include <contact_dynamics/scenes/body_mesh.h>
#include <contact_dynamics/scenes/scene_registry.h>

#include <array>

namespace ContactDynamics
{
  namespace
  {
    template <int dim>
    class Block : public BuiltInScene<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Block");
        prm.declare_entry("Origin",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Lower left (front) corner of the box, one "
                          "coordinate per space dimension.");
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
        prm.leave_subsection();
      }

    protected:
      void
      parse_scene_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Block");
        // The patterns allow 2 or 3 entries; the space dimension decides.
        const auto list = [&](const std::string &entry) {
          const std::string              value = prm.get(entry);
          const std::vector<std::string> items =
            Utilities::split_string_list(value);
          AssertThrow(
            items.size() == dim,
            ExcMessage("The parameter Scene/Block/" + entry + " = '" + value +
                       "' has " + std::to_string(items.size()) +
                       " entries, but the problem is " + std::to_string(dim) +
                       "-D: give exactly " + std::to_string(dim) + " values."));
          return items;
        };
        const std::vector<double> origin =
          Utilities::string_to_double(list("Origin"));
        const std::vector<double> size =
          Utilities::string_to_double(list("Size"));
        const std::vector<int> subdivisions =
          Utilities::string_to_int(list("Subdivisions"));
        for (unsigned int d = 0; d < dim; ++d)
          {
            p0[d]         = origin[d];
            p1[d]         = origin[d] + size[d];
            n_elements[d] = subdivisions[d];
          }
        prm.leave_subsection();
      }

      std::vector<BodyDefinition<dim>>
      bodies() const override
      {
        std::vector<unsigned int> n(dim);
        for (unsigned int d = 0; d < dim; ++d)
          n[d] = this->scaled(n_elements[d]);
        return {box_body("body", p0, p1, n, "")};
      }

    private:
      Point<dim>                  p0, p1;
      std::array<unsigned int, 3> n_elements;
    };
  } // namespace

  SceneEntry
  block_scene()
  {
    return scene_in_any_dimension<Block>("block",
                                         "one box, see subsection Block");
  }
} // namespace ContactDynamics
