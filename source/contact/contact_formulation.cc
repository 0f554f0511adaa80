#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/mortar_contact.h>
#include <contact_dynamics/contact/node_to_segment_contact.h>
#include <contact_dynamics/parameters.h>

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
  } // namespace

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    const ContactParameters defaults;
    prm.declare_entry("Formulation",
                      formulation_names.name(defaults.formulation),
                      formulation_names.pattern(),
                      "'none': the bodies do not interact (no multiplier "
                      "unknowns, no cost). 'mortar': dual mortar "
                      "segment-to-segment contact with Lagrange multipliers "
                      "on the secondary surfaces (2-D). 'nts': "
                      "node-to-segment contact, each secondary node "
                      "projected onto the primary surface, enforced with "
                      "nodal multipliers (2-D).");
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
                      "Points 'x, y' separated by ';' (reference "
                      "coordinates); the nearest secondary node of each is "
                      "written to contact_history.csv at every step.");
  }

  void
  ContactParameters::parse_parameters(ParameterHandler  &prm,
                                      const SceneLayout &layout)
  {
    formulation = formulation_names.value(prm.get("Formulation"));
    pairs.clear();
    const auto side = [&](const std::string &text, const std::string &entry) {
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
    };
    for (const auto &entry :
         Utilities::split_string_list(prm.get("Pairs"), ';'))
      {
        const auto colon = entry.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                               "' is not of the form 'secondary: primary'."));
        ContactPair pair;
        pair.secondary = side(entry.substr(0, colon), entry);
        pair.primary   = side(entry.substr(colon + 1), entry);
        pair.name      = entry;
        for (const auto id : pair.secondary)
          AssertThrow(std::find(pair.primary.begin(), pair.primary.end(), id) ==
                        pair.primary.end(),
                      ExcMessage("In 'Contact/Pairs', the entry '" + entry +
                                 "' has a surface on both sides."));
        pairs.push_back(pair);
      }
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
    AssertThrow(formulation == Formulation::none || !pairs.empty(),
                ExcMessage("Contact/Formulation = " +
                           formulation_names.name(formulation) +
                           " needs at least one pair in 'Contact/Pairs'."));

    allow_initial_penetration =
      penetration_names.value(prm.get("Initial penetration"));
    monitored_points.clear();
    for (const auto &text :
         Utilities::split_string_list(prm.get("Monitored points"), ';'))
      {
        const auto xy = Utilities::split_string_list(text, ',');
        AssertThrow(xy.size() == 2,
                    ExcMessage("In 'Contact/Monitored points', '" + text +
                               "' is not a point 'x, y'."));
        try
          {
            monitored_points.emplace_back(Utilities::string_to_double(xy[0]),
                                          Utilities::string_to_double(xy[1]));
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage("In 'Contact/Monitored points', '" + text +
                                   "' is not a point 'x, y'."));
          }
      }
  }

  void
  declare_contact_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    ContactParameters::declare_parameters(prm);
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
    contact.parse_parameters(prm, layout);
    prm.enter_subsection("Mortar");
    MortarParameters mortar;
    mortar.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Node to segment");
    NodeToSegmentParameters nts;
    nts.parse_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();

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

  template std::unique_ptr<ContactFormulation<2>>
  create_contact_formulation<2>(ParameterHandler &, const SceneLayout &);
  template std::unique_ptr<ContactFormulation<3>>
  create_contact_formulation<3>(ParameterHandler &, const SceneLayout &);
} // namespace ContactDynamics
