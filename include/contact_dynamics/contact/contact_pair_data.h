// What SurfaceContact keeps per contact pair: the surfaces, the search
// results, the nodal sums the patches assemble, the parallel distribution
// of nodes and patches, and (as bases, so that the formulations read
// pair.nodes, pair.obstacle, ...) the pieces of history with their own
// owners: the node history and the obstacle coupling.
#ifndef contact_dynamics_contact_contact_pair_data_h
#define contact_dynamics_contact_contact_pair_data_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <contact_dynamics/contact/complementarity_parameters.h>
#include <contact_dynamics/contact/contact_formulation.h>
#include <contact_dynamics/contact/contact_surface.h>
#include <contact_dynamics/contact/rigid_obstacle.h>

#include <array>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace ContactDynamics
{
  /**
   * The history of a pair's secondary nodes (owner: NodeHistory in
   * node_history.h): their states and their positions at the last
   * committed step.
   */
  template <int dim>
  struct PairNodeHistory
  {
    std::vector<ContactNodeState> nodes;
    // secondary nodes at the last committed step
    std::vector<Point<dim>> position;
  };

  /**
   * A rigid obstacle as the primary side of a pair (owner: ObstacleCoupling
   * in obstacle_coupling.h): the obstacle (null for a meshed primary
   * surface), its placements, the tangent axes of the nodes and the
   * reaction on it.
   */
  template <int dim>
  struct PairObstacle
  {
    // at the committed and the trial time; per secondary node the axis its
    // tangents are built from (3-D, tangent_basis())
    std::shared_ptr<const RigidObstacle<dim>> obstacle;
    typename RigidObstacle<dim>::Placement    committed_place, trial_place;
    std::vector<unsigned int>                 tangent_axis;
    std::map<types::global_dof_index, std::pair<unsigned int, unsigned int>>
      dof_node; // displacement dof -> (node, component)
    // on the obstacle at the trial state and at the last committed step:
    // force, torque about its center (3 components; z only in 2-D) and
    // their friction parts
    struct Reaction
    {
      Tensor<1, dim> force, friction_force;
      Tensor<1, 3>   torque, friction_torque;
    };
    Reaction reaction, committed_reaction;
  };

  template <int dim>
  struct ContactPairData : PairNodeHistory<dim>, PairObstacle<dim>
  {
    unsigned int        index = 0;          // in the formulation's pairs
    ContactSurface<dim> secondary, primary; // primary: empty for an obstacle
    std::vector<std::vector<unsigned int>> candidates; // per patch
    std::vector<std::vector<unsigned int>> pattern;    // in the sparsity
    // per secondary node: gap, its normalization weight, gap rate,
    // relative tangential velocity (secondary minus primary) along the
    // node's dim - 1 tangents
    std::vector<LinearizedValue>                      gap, weight, gap_rate;
    std::vector<std::array<LinearizedValue, dim - 1>> slip_rate;
    double                                            friction_coefficient = 0;
    // in parallel: the nodes whose multipliers this process owns, the
    // patches that touch them (whose candidates and couplings it needs)
    // and the patches it computes (an equal share of all: the contact
    // surface may lie on one process's part of the mesh); a patch's
    // contributions to a node go to the node's owner (node_owner)
    std::vector<bool>         owned_node, handled_patch, assembled_patch;
    std::vector<unsigned int> node_owner;
    // per secondary node that hangs on an adapted 3-D mesh: the nodes it
    // follows and their weights (empty for a node with its own unknowns)
    std::vector<std::vector<std::pair<unsigned int, double>>> hanging_parents;
    // per primary face of degree 2 in 3-D and per edge: into how many parts
    // finer faces that hang on it divide it (HangingSurfaceDofs)
    std::vector<std::array<unsigned int, 4>> primary_edge_subdivisions;

    /** What the patches add up at node j. */
    std::vector<LinearizedValue *>
    node_sums(const unsigned int j)
    {
      std::vector<LinearizedValue *> sums{&gap[j], &weight[j], &gap_rate[j]};
      for (auto &v : slip_rate[j])
        sums.push_back(&v);
      return sums;
    }
  };
} // namespace ContactDynamics

#endif
