#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace ContactDynamics
{
  namespace
  {
    const Selection<ContactParameters::Formulation> formulation_names{
      {ContactParameters::Formulation::none, "none"},
      {ContactParameters::Formulation::mortar, "mortar"},
      {ContactParameters::Formulation::node_to_segment, "nts"}};

    const Selection<bool> penetration_names{{false, "stop"}, {true, "allow"}};

    /**
     * The rigid obstacles of the scene, parsed from their subsections into
     * `obstacles` (in the order of the layout).
     */
    void
    parse_obstacles(ParameterHandler                     &prm,
                    const SceneLayout                    &layout,
                    const unsigned int                    dim,
                    std::vector<RigidObstacleParameters> &obstacles)
    {
      for (const auto &name : layout.obstacle_names)
        {
          RigidObstacleParameters obstacle;
          prm.enter_subsection(RigidObstacleParameters::subsection_name(name));
          obstacle.parse_parameters(prm, dim, name);
          prm.leave_subsection();
          AssertThrow(layout.surfaces.count(name) == 0,
                      ExcMessage("In 'Contact/Rigid obstacles', the name '" +
                                 name +
                                 "' is also a surface of the scene: give the "
                                 "obstacle another name."));
          obstacles.push_back(obstacle);
        }
    }

    /**
     * The entries of 'Contact/Pairs', one at a time, checked against the
     * layout, the obstacles and the pairs read before.
     */
    class PairParser
    {
    public:
      PairParser(const SceneLayout                          &layout,
                 const std::vector<RigidObstacleParameters> &obstacles)
        : layout(layout)
        , obstacles(obstacles)
      {
        for (const auto &[name, id] : layout.surfaces)
          surface_name[id] = name;
      }

      /** Parses `entry` and appends it to `pairs`. */
      void
      add(const std::string &entry, std::vector<ContactPair> &pairs)
      {
        ContactPair pair = sides(entry);
        if (pair.obstacle >= 0)
          {
            check_obstacle_pair(pair, pairs);
            pairs.push_back(pair);
            return;
          }
        check_surface_pair(pair, pairs);
        pairs.push_back(pair);
      }

    private:
      int
      obstacle_index(const std::string &text) const
      {
        const std::string name = Utilities::trim(text);
        for (unsigned int k = 0; k < obstacles.size(); ++k)
          if (obstacles[k].name == name)
            return int(k);
        return -1;
      }

      std::vector<types::boundary_id>
      side(const std::string &text, const std::string &entry) const
      {
        std::vector<types::boundary_id> ids;
        for (const auto &name : Utilities::split_string_list(text, '+'))
          {
            try
              {
                ids.push_back(layout.surface_id(name));
              }
            catch (const ExceptionBase &e)
              {
                std::ostringstream message;
                e.print_info(message);
                AssertThrow(false,
                            ExcMessage("In 'Contact/Pairs', entry '" + entry +
                                       "': " + Utilities::trim(message.str())));
              }
          }
        AssertThrow(!ids.empty(),
                    ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                               "' has an empty side."));
        return ids;
      }

      /** The first surface of `a` that is also in `b`, or none. */
      static std::optional<types::boundary_id>
      common(const std::vector<types::boundary_id> &a,
             const std::vector<types::boundary_id> &b)
      {
        for (const auto id : a)
          if (std::find(b.begin(), b.end(), id) != b.end())
            return std::optional<types::boundary_id>(id);
        return std::optional<types::boundary_id>();
      }

      /** The two sides of `entry` ('secondary: primary'). */
      ContactPair
      sides(const std::string &entry)
      {
        const auto colon = entry.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                               "' is not of the form 'secondary: primary'."));
        ContactPair pair;
        pair.name = entry;
        for (const auto &name :
             Utilities::split_string_list(entry.substr(0, colon), '+'))
          AssertThrow(obstacle_index(name) < 0,
                      ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                                 "' has the rigid obstacle '" + name +
                                 "' on the secondary side: an obstacle "
                                 "carries no multipliers and can only be the "
                                 "primary side, alone."));
        pair.secondary = side(entry.substr(0, colon), entry);
        pair.obstacle  = obstacle_index(entry.substr(colon + 1));
        if (pair.obstacle < 0)
          {
            for (const auto &name :
                 Utilities::split_string_list(entry.substr(colon + 1), '+'))
              AssertThrow(obstacle_index(name) < 0,
                          ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                                     "' joins the rigid obstacle '" + name +
                                     "' with other surfaces: an obstacle is "
                                     "a primary side alone."));
            pair.primary = side(entry.substr(colon + 1), entry);
          }
        for (const auto *ids : {&pair.secondary, &pair.primary})
          for (auto id = ids->begin(); id != ids->end(); ++id)
            AssertThrow(std::find(id + 1, ids->end(), *id) == ids->end(),
                        ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                                   "' names the surface '" + surface_name[*id] +
                                   "' twice on one side."));
        return pair;
      }

      /** An obstacle touches any body; a surface meets it once. */
      void
      check_obstacle_pair(const ContactPair              &pair,
                          const std::vector<ContactPair> &pairs)
      {
        const std::string &entry = pair.name;
        for (const ContactPair &other : pairs)
          if (other.obstacle == pair.obstacle)
            if (const auto id = common(pair.secondary, other.secondary))
              AssertThrow(false,
                          ExcMessage("In 'Contact/Pairs', the entries '" +
                                     other.name + "' and '" + entry +
                                     "' both pair the surface '" +
                                     surface_name[*id] +
                                     "' with the rigid obstacle: remove "
                                     "one of them."));
      }

      /** A pair of mesh surfaces: different surfaces, bodies, pairs. */
      void
      check_surface_pair(const ContactPair              &pair,
                         const std::vector<ContactPair> &pairs)
      {
        const std::string &entry = pair.name;
        if (const auto id = common(pair.secondary, pair.primary))
          AssertThrow(false,
                      ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                                 "' has the surface '" + surface_name[*id] +
                                 "' on both sides."));

        // the formulations find contact between different bodies only
        if (!layout.surface_body.empty())
          for (const auto s : pair.secondary)
            for (const auto p : pair.primary)
              {
                const auto body = layout.surface_body.at(surface_name[s]);
                AssertThrow(
                  body != layout.surface_body.at(surface_name[p]),
                  ExcMessage(
                    "In 'Contact/Pairs', the entry '" + entry +
                    "' pairs the surfaces '" + surface_name[s] + "' and '" +
                    surface_name[p] + "' of the same body '" +
                    layout.body_names[body] +
                    "': contact of a body with itself is not supported. "
                    "Pair surfaces of two different bodies."));
              }

        // a second pair between the same surfaces (in either role) would
        // add its contact forces to the first one's
        for (const ContactPair &other : pairs)
          {
            auto a = common(pair.secondary, other.secondary);
            auto b = common(pair.primary, other.primary);
            if (!a || !b)
              {
                a = common(pair.secondary, other.primary);
                b = common(pair.primary, other.secondary);
              }
            AssertThrow(!a || !b,
                        ExcMessage(
                          "In 'Contact/Pairs', the entries '" + other.name +
                          "' and '" + entry + "' both pair the surfaces '" +
                          surface_name[*a] + "' and '" + surface_name[*b] +
                          "': two surfaces may be paired once only (a "
                          "second pair would count their contact force "
                          "twice). Remove one of the entries."));
          }
      }

      const SceneLayout                          &layout;
      const std::vector<RigidObstacleParameters> &obstacles;
      std::map<types::boundary_id, std::string>   surface_name;
    };

    /** 'Contact/Friction coefficients': one for all pairs or one each. */
    void
    parse_friction_coefficients(ParameterHandler         &prm,
                                std::vector<ContactPair> &pairs)
    {
      const auto mu =
        Utilities::split_string_list(prm.get("Friction coefficients"), ';');
      AssertThrow(mu.size() == 1 || mu.size() == pairs.size(),
                  ExcMessage("'Contact/Friction coefficients' = '" +
                             prm.get("Friction coefficients") + "' has " +
                             std::to_string(mu.size()) +
                             " values; give one, or one per pair (" +
                             std::to_string(pairs.size()) + ")."));
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          const std::string &text  = mu[mu.size() == 1 ? 0 : p];
          double             value = -1;
          try
            {
              value = Utilities::string_to_double(text);
            }
          catch (...)
            {}
          AssertThrow(value >= 0 && value <= 10,
                      ExcMessage("'Contact/Friction coefficients': '" + text +
                                 "' is not a number in [0, 10]."));
          pairs[p].friction_coefficient = value;
        }
    }

    /** 'Contact/Monitored points', appended to `points`. */
    void
    parse_monitored_points(ParameterHandler                 &prm,
                           std::vector<std::vector<double>> &points)
    {
      for (const auto &text :
           Utilities::split_string_list(prm.get("Monitored points"), ';'))
        {
          const std::string what = "In 'Contact/Monitored points', '" + text +
                                   "' is not a point 'x, y' (3-D: 'x, y, z')";
          const auto coordinates = Utilities::split_string_list(text, ',');
          AssertThrow(coordinates.size() == 2 || coordinates.size() == 3,
                      ExcMessage(what + "."));
          std::vector<double> point;
          for (const auto &c : coordinates)
            {
              try
                {
                  point.push_back(Utilities::string_to_double(c));
                }
              catch (...)
                {
                  AssertThrow(false, ExcMessage(what + "."));
                }
              AssertThrow(std::isfinite(point.back()),
                          ExcMessage(what + " of finite numbers."));
            }
          points.push_back(point);
        }
    }
  } // namespace

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    const ContactParameters defaults;
    prm.declare_entry("Formulation",
                      formulation_names.name(defaults.formulation),
                      formulation_names.pattern(),
                      "'none': the bodies do not interact (no multiplier "
                      "unknowns, no cost; Pairs and Rigid obstacles must "
                      "then be empty). 'mortar': dual mortar "
                      "segment-to-segment contact with Lagrange multipliers "
                      "on the secondary surfaces (2-D and 3-D). 'nts': "
                      "node-to-segment contact, each secondary node "
                      "projected onto the primary surface, enforced with "
                      "nodal multipliers (2-D and 3-D).");
    prm.declare_entry(
      "Pairs",
      "",
      Patterns::Anything(),
      "Contact pairs 'secondary: primary', separated by ';'. A side may join "
      "several surfaces with '+', e.g. 'tool_arc + tool_sides: "
      "substrate_top'. The secondary side carries the multipliers: choose the "
      "finer surface.");
    prm.declare_entry("Friction coefficients",
                      "0",
                      Patterns::Anything(),
                      "Coulomb friction coefficient mu >= 0 of each pair, "
                      "separated by ';' in the order of 'Pairs', or one value "
                      "for all. 0 = frictionless (no tangential unknowns).");
    prm.declare_entry(
      "Initial penetration",
      penetration_names.name(defaults.allow_initial_penetration),
      penetration_names.pattern(),
      "Bodies that overlap at t = 0 (by more than the capture tolerance): "
      "'stop' ends the run with a message that says where; 'allow' warns "
      "and lets the contact push them apart in the first steps, which "
      "creates energy (reported in contact_work and the energy balance "
      "error).");
    prm.declare_entry("Monitored points",
                      "",
                      Patterns::Anything(),
                      "Points 'x, y' (3-D: 'x, y, z') separated by ';' "
                      "(reference coordinates); the nearest secondary node "
                      "of each is "
                      "written to contact_history.csv at every step. A "
                      "point must lie within one element (the longest face "
                      "at that node) of a secondary node.");
  }

  void
  ContactParameters::parse_parameters(ParameterHandler  &prm,
                                      const SceneLayout &layout,
                                      const unsigned int dim)
  {
    formulation = formulation_names.value(prm.get("Formulation"));
    body_names  = layout.body_names;
    pairs.clear();
    obstacles.clear();
    parse_obstacles(prm, layout, dim, obstacles);
    PairParser pair_parser(layout, obstacles);
    for (const auto &entry :
         Utilities::split_string_list(prm.get("Pairs"), ';'))
      pair_parser.add(entry, pairs);
    parse_friction_coefficients(prm, pairs);
    AssertThrow(formulation == Formulation::none || !pairs.empty(),
                ExcMessage("Contact/Formulation = " +
                           formulation_names.name(formulation) +
                           " needs at least one pair in 'Contact/Pairs'."));
    // (ignored, the bodies would pass through each other and the obstacles)
    AssertThrow(
      formulation != Formulation::none || (pairs.empty() && obstacles.empty()),
      ExcMessage("Contact/Formulation = none enforces no contact, but " +
                 (pairs.empty() ? "" :
                                  "'Contact/Pairs' = '" + prm.get("Pairs") +
                                    "'" + (obstacles.empty() ? "" : " and ")) +
                 (obstacles.empty() ? "" :
                                      "'Contact/Rigid obstacles' = '" +
                                        prm.get("Rigid obstacles") + "'") +
                 (!pairs.empty() && !obstacles.empty() ? " are" : " is") +
                 " set: choose Formulation = mortar or nts, or remove " +
                 (!pairs.empty() && !obstacles.empty() ? "them." : "it.")));

    allow_initial_penetration =
      penetration_names.value(prm.get("Initial penetration"));
    monitored_points.clear();
    parse_monitored_points(prm, monitored_points);
  }

  namespace
  {
    void
    declare_obstacle_entry(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Rigid obstacles",
        "",
        Patterns::Anything(),
        "Names of rigid obstacles, separated by ','; each gets a subsection "
        "'Rigid obstacle <name>' (shape and prescribed motion) and may be "
        "the primary side of pairs in 'Pairs' (e.g. 'block_bottom: "
        "ground'). An obstacle is an analytic surface with no mesh and no "
        "unknowns; its reaction force and torque are written to "
        "statistics.csv.");
    }
  } // namespace

  void
  declare_obstacle_names(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    declare_obstacle_entry(prm);
    prm.leave_subsection();
  }

  std::vector<std::string>
  obstacle_names(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string text = prm.get("Rigid obstacles");
    prm.leave_subsection();
    const auto names = Utilities::split_string_list(text, ',');
    for (auto name = names.begin(); name != names.end(); ++name)
      AssertThrow(!name->empty() &&
                    name->find_first_of(":;+") == std::string::npos &&
                    std::find(name + 1, names.end(), *name) == names.end(),
                  ExcMessage("'Contact/Rigid obstacles' = '" + text +
                             "': the name '" + *name +
                             "' is empty, repeated or contains ':', ';' or "
                             "'+'."));
    return names;
  }

  void
  declare_contact_parameters(ParameterHandler  &prm,
                             const SceneLayout &layout,
                             const unsigned int dim)
  {
    prm.enter_subsection("Contact");
    ContactParameters::declare_parameters(prm);
    declare_obstacle_entry(prm);
    for (const auto &name : layout.obstacle_names)
      {
        prm.enter_subsection(RigidObstacleParameters::subsection_name(name));
        RigidObstacleParameters::declare_parameters(prm, dim);
        prm.leave_subsection();
      }
    prm.enter_subsection("Mortar");
    MortarParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Node to segment");
    NodeToSegmentParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  create_contact_formulation(ParameterHandler &prm, const SceneLayout &layout)
  {
    prm.enter_subsection("Contact");
    ContactParameters contact;
    contact.parse_parameters(prm, layout, dim);
    prm.enter_subsection("Mortar");
    MortarParameters mortar;
    mortar.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Node to segment");
    NodeToSegmentParameters nts;
    nts.parse_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    for (const std::string &body : layout.body_names)
      {
        prm.enter_subsection("Body " + body);
        contact.youngs_moduli.push_back(prm.get_double("Young's modulus"));
        prm.leave_subsection();
      }

    for (const auto &point : contact.monitored_points)
      AssertThrow(point.size() == dim,
                  ExcMessage(
                    "In 'Contact/Monitored points', a point has " +
                    std::to_string(point.size()) +
                    " coordinates; with Dimension = " + std::to_string(dim) +
                    " give " + (dim == 2 ? "'x, y'." : "'x, y, z'.")));

    switch (contact.formulation)
      {
        case ContactParameters::Formulation::mortar:
          return std::make_unique<MortarContact<dim>>(contact, mortar);
        case ContactParameters::Formulation::node_to_segment:
          return std::make_unique<NodeToSegmentContact<dim>>(contact, nts);
        case ContactParameters::Formulation::none:
          break;
      }
    return nullptr;
  }

  namespace
  {
    /**
     * Gmsh scenes only know the bodies of their surfaces from the mesh
     * (the built-in ones were checked when the parameters were read).
     */
    template <int dim>
    void
    check_pair_bodies(const ContactParameters  &contact,
                      const Triangulation<dim> &triangulation)
    {
      std::map<types::boundary_id, std::set<types::material_id>> bodies_of;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            bodies_of[face->boundary_id()].insert(cell->material_id());
      for (const ContactPair &pair : contact.pairs)
        {
          std::set<types::material_id> secondary;
          for (const auto id : pair.secondary)
            secondary.insert(bodies_of[id].begin(), bodies_of[id].end());
          for (const auto id : pair.primary)
            for (const auto body : bodies_of[id])
              AssertThrow(secondary.count(body) == 0,
                          ExcMessage(
                            "In 'Contact/Pairs', both sides of the entry '" +
                            pair.name + "' are surfaces of the body '" +
                            (body < contact.body_names.size() ?
                               contact.body_names[body] :
                               std::to_string(body)) +
                            "': contact of a body with itself is not "
                            "supported. Pair surfaces of two different "
                            "bodies."));
        }
    }

    /** A node this far from contact would still count as in contact. */
    template <int dim>
    void
    check_capture_tolerance(
      const ContactParameters                                       &contact,
      const std::vector<std::array<const ContactSurface<dim> *, 2>> &surfaces,
      const double capture_tolerance)
    {
      const std::string capture_parameter =
        std::string("Contact/") +
        (contact.formulation == ContactParameters::Formulation::mortar ?
           "Mortar" :
           "Node to segment") +
        "/Capture tolerance";
      double       shortest = std::numeric_limits<double>::max();
      unsigned int where    = 0;
      for (unsigned int p = 0; p < surfaces.size(); ++p)
        for (const ContactSurface<dim> *surface : surfaces[p])
          for (const auto &face : surface->faces)
            {
              const double length = surface->reference[face[0]].distance(
                surface->reference[face[1]]);
              if (length < shortest)
                {
                  shortest = length;
                  where    = p;
                }
            }
      if (!surfaces.empty())
        {
          std::ostringstream message;
          message << capture_parameter << " = " << capture_tolerance
                  << " is more than a tenth of the shortest contact face ("
                  << shortest << ", pair '" << contact.pairs[where].name
                  << "'): nodes that far apart would count as in contact and "
                     "be held there. Allowed: 0 to "
                  << 0.1 * shortest
                  << " for this mesh; the default 1e-5 suits elements down "
                     "to 1e-4.";
          // (the bound itself is allowed; face lengths carry round-off)
          AssertThrow(capture_tolerance <= 0.1 * shortest * (1 + 1e-10),
                      ExcMessage(message.str()));
        }
    }

    /**
     * The element size at a node of a surface: the longest of its faces
     * (the face's length in 2-D, its longer diagonal in 3-D).
     */
    template <int dim>
    double
    element_size_at(const ContactSurface<dim> &surface, const unsigned int node)
    {
      double size = 0;
      for (const unsigned int f : surface.node_faces[node])
        {
          const auto &x = surface.faces[f];
          size          = std::max(size,
                          surface.reference[x[0]].distance(
                            surface.reference[x.back()]));
          if constexpr (dim == 3)
            size = std::max(size,
                            surface.reference[x[1]].distance(
                              surface.reference[x[2]]));
        }
      return size;
    }

    /** The output follows the nearest secondary node of a monitored point. */
    template <int dim>
    void
    check_monitored_points(
      const ContactParameters                                       &contact,
      const std::vector<std::array<const ContactSurface<dim> *, 2>> &surfaces)
    {
      for (const auto &point : contact.monitored_points)
        {
          double       best = std::numeric_limits<double>::max();
          unsigned int pair = 0, node = 0;
          for (unsigned int p = 0; p < surfaces.size(); ++p)
            for (unsigned int j = 0; j < surfaces[p][0]->n_nodes(); ++j)
              {
                double d = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  d += std::pow(surfaces[p][0]->reference[j][k] - point[k], 2);
                if (d < best)
                  {
                    best = d;
                    pair = p;
                    node = j;
                  }
              }
          if (surfaces.empty())
            break;
          const ContactSurface<dim> &surface = *surfaces[pair][0];
          const double               size    = element_size_at(surface, node);
          std::ostringstream         message;
          const Point<dim>          &X           = surface.reference[node];
          const auto                 coordinates = [](const auto &x) {
            std::ostringstream text;
            text << '(';
            for (unsigned int k = 0; k < dim; ++k)
              text << (k ? ", " : "") << x[k];
            return text.str() + ')';
          };
          message << "In 'Contact/Monitored points', the point "
                  << coordinates(point) << " is " << std::sqrt(best)
                  << " from the nearest secondary contact node, "
                  << coordinates(X) << " of the pair '"
                  << contact.pairs[pair].name
                  << "', more than the element size there (" << size
                  << "). A monitored point must lie on a secondary surface, "
                     "within one element of one of its nodes (reference "
                     "coordinates).";
          AssertThrow(std::sqrt(best) <= size, ExcMessage(message.str()));
        }
    }
  } // namespace

  template <int dim>
  void
  check_contact_setup(
    const ContactParameters                                       &contact,
    const std::vector<std::array<const ContactSurface<dim> *, 2>> &surfaces,
    const double              capture_tolerance,
    const Triangulation<dim> &triangulation)
  {
    AssertDimension(surfaces.size(), contact.pairs.size());
    check_pair_bodies(contact, triangulation);
    check_capture_tolerance(contact, surfaces, capture_tolerance);
    check_monitored_points(contact, surfaces);
  }

  template void
  check_contact_setup(
    const ContactParameters &,
    const std::vector<std::array<const ContactSurface<2> *, 2>> &,
    const double,
    const Triangulation<2> &);
  template void
  check_contact_setup(
    const ContactParameters &,
    const std::vector<std::array<const ContactSurface<3> *, 2>> &,
    const double,
    const Triangulation<3> &);

  template std::unique_ptr<ContactFormulation<2>>
  create_contact_formulation<2>(ParameterHandler &, const SceneLayout &);
  template std::unique_ptr<ContactFormulation<3>>
  create_contact_formulation<3>(ParameterHandler &, const SceneLayout &);
} // namespace ContactDynamics
