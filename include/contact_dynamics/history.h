// State that outlives a Newton iteration. Every such value has exactly one
// owner, which implements the value's whole lifecycle side by side: start
// an attempt (roll back to the committed state), commit, save to and load
// from a checkpoint, transfer on a mesh change, and list the vectors on the
// degree-of-freedom layout. A class that holds history (the Simulator, a
// contact formulation) keeps a HistoryRegistry; its lifecycle functions are
// calls of the registry, so that a feature with history of its own adds an
// owner and one registration line, never a branch to them (in the spirit of
// ASPECT's serialize() and refinement signals, and Lethe's per-physics
// checkpoints; doc/architecture.md, "History").
#ifndef contact_dynamics_history_h
#define contact_dynamics_history_h

#include <contact_dynamics/solvers/trilinos_forward.h>

#include <memory>
#include <string>
#include <vector>

namespace ContactDynamics
{
  using namespace dealii;

  class CheckpointData;

  /**
   * One owner of history. `Context` is what the holder passes to every
   * call (for a contact formulation: the committed state and the mesh).
   * Checkpoint entries are named by the owner (prefix them with name()).
   */
  template <typename Context>
  class HistoryOwner
  {
  public:
    virtual ~HistoryOwner() = default;

    /** Names the owner in checkpoint entries and messages. */
    virtual std::string
    name() const = 0;

    /** Before an attempt of a step: back to the committed values. */
    virtual void
    start_attempt(const Context &)
    {}

    /** The step was accepted: the trial values become the committed ones. */
    virtual void
    commit(const Context &) = 0;

    virtual void
    save(CheckpointData &data, const Context &context) const = 0;

    /** The values save() wrote (throws naming the entry if one is bad). */
    virtual void
    load(const CheckpointData &data, const Context &context) = 0;

    /**
     * After a mesh change (the vectors of list_vectors() were moved to the
     * new mesh already): make the rest consistent with the new mesh.
     */
    virtual void
    transfer(const Context &)
    {}

    /** Vectors on the degree-of-freedom layout a checkpoint saves. */
    virtual void
    list_vectors(std::vector<TrilinosWrappers::MPI::Vector *> &)
    {}

    /**
     * Before a mesh change: the vectors to interpolate to the new mesh (the
     * others are rebuilt, or evaluated again, after it).
     */
    virtual void
    prepare_transfer(std::vector<TrilinosWrappers::MPI::Vector *> &)
    {}

    /**
     * Before a checkpoint's vectors are read into those of list_vectors()
     * (after load() and the setup of the loaded mesh): the owner's own
     * vectors take the layout of `layout`.
     */
    virtual void
    reinit_vectors(const TrilinosWrappers::MPI::Vector & /*layout*/)
    {}
  };

  /**
   * The owners of one holder, called in the order of registration. `Owner`:
   * their class, if the holder asks more of them than HistoryOwner does.
   */
  template <typename Context, typename Owner = HistoryOwner<Context>>
  class HistoryRegistry
  {
  public:
    /** The owner must outlive the registry. */
    void
    add(Owner &owner)
    {
      owners.push_back(&owner);
    }

    /** An owner the registry keeps (one line registers a new feature). */
    void
    add(std::unique_ptr<Owner> owner)
    {
      owners.push_back(owner.get());
      kept.push_back(std::move(owner));
    }

    /** The owners in the order of registration. */
    const std::vector<Owner *> &
    all() const
    {
      return owners;
    }

    void
    start_attempt(const Context &context) const
    {
      for (auto *owner : owners)
        owner->start_attempt(context);
    }

    void
    commit(const Context &context) const
    {
      for (auto *owner : owners)
        owner->commit(context);
    }

    void
    save(CheckpointData &data, const Context &context) const
    {
      for (const auto *owner : owners)
        owner->save(data, context);
    }

    void
    load(const CheckpointData &data, const Context &context) const
    {
      for (auto *owner : owners)
        owner->load(data, context);
    }

    void
    transfer(const Context &context) const
    {
      for (auto *owner : owners)
        owner->transfer(context);
    }

    void
    reinit_vectors(const TrilinosWrappers::MPI::Vector &layout) const
    {
      for (auto *owner : owners)
        owner->reinit_vectors(layout);
    }

    std::vector<TrilinosWrappers::MPI::Vector *>
    prepare_transfer() const
    {
      std::vector<TrilinosWrappers::MPI::Vector *> result;
      for (auto *owner : owners)
        owner->prepare_transfer(result);
      return result;
    }

    std::vector<TrilinosWrappers::MPI::Vector *>
    vectors() const
    {
      std::vector<TrilinosWrappers::MPI::Vector *> result;
      for (auto *owner : owners)
        owner->list_vectors(result);
      return result;
    }

    void
    clear()
    {
      owners.clear();
      kept.clear();
    }

  private:
    std::vector<Owner *>                owners;
    std::vector<std::unique_ptr<Owner>> kept;
  };
} // namespace ContactDynamics

#endif
