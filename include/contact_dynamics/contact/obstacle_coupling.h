// The owner of the coupling of the contact pairs whose primary side is a
// rigid obstacle (PairObstacle in contact_pair_data.h): the placements at
// the committed and the trial time, the nodes' tangent axes, the reaction
// on the obstacles and the work they did on the bodies, with their
// statistics columns and checkpoint entries.
#ifndef contact_dynamics_contact_obstacle_coupling_h
#define contact_dynamics_contact_obstacle_coupling_h

#include <contact_dynamics/contact/contact_history.h>
#include <contact_dynamics/contact/contact_pair_data.h>
#include <contact_dynamics/contact/patch_forces.h>

#include <string>
#include <vector>

namespace ContactDynamics
{
  class ProcessSums;

  template <int dim>
  class ObstacleCoupling : public ContactHistoryOwner
  {
  public:
    ObstacleCoupling(std::vector<ContactPairData<dim>> &pairs,
                     const ContactParameters           &contact)
      : pairs(pairs)
      , contact(contact)
    {}

    std::string
    name() const override
    {
      return "rigid obstacles";
    }

    /** The obstacle of a pair, its placements and node maps. */
    void
    set_up(ContactPairData<dim>          &pair,
           const RigidObstacleParameters &parameters) const;

    /** Places the obstacles at the committed and the trial time. */
    void
    set_times(const double committed, const double trial);

    /** Adds a patch's forces to the reaction on the pair's obstacle. */
    void
    add_reaction(ContactPairData<dim> &pair,
                 const PatchForces    &forces,
                 const VectorType     &u) const;

    /** The reactions of this process, to be summed over all. */
    void
    add_to_sums(ProcessSums &sums);

    /**
     * The obstacles' work in the step: minus the power of the reactions
     * on their rigid motions, trapezoidal in time; the reactions become
     * the committed ones.
     */
    void
    commit(const ContactHistoryContext &) override;

    /** Per pair the committed reaction and the tangent axes; the work. */
    void
    save(CheckpointData &data, const ContactHistoryContext &) const override;
    void
    load(const CheckpointData        &data,
         const ContactHistoryContext &context) override;

    /** Per obstacle the reaction on it; the work they did on the bodies. */
    void
    add_columns(std::vector<std::string> &columns) const;

    /** Their values. */
    void
    add_statistics(std::vector<double> &values) const;

    /** The work the obstacles did on the bodies so far. */
    double
    work() const
    {
      return work_done;
    }

    /** Its friction part. */
    double
    friction_work() const
    {
      return friction_work_done;
    }

    /** The normal (frictionless) part of the work in the last step. */
    double
    normal_step_work() const
    {
      return last_normal_work;
    }

  private:
    std::vector<ContactPairData<dim>> &pairs;
    const ContactParameters           &contact;
    double                             committed_time = 0, trial_time = 0;
    double work_done = 0, friction_work_done = 0, last_normal_work = 0;
  };
} // namespace ContactDynamics

#endif
