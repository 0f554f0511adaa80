// Checkpoints: what a run needs to continue exactly where it stopped, as
// named arrays of numbers and texts in one file, and the directories that
// hold them (written under a temporary name, renamed when complete, the
// last two kept).
#ifndef contact_dynamics_output_checkpoint_h
#define contact_dynamics_output_checkpoint_h

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ContactDynamics
{
  /**
   * Named arrays of doubles (integers up to 2^53 are exact) and named texts.
   * A missing or mis-sized entry on reading is an error that names the
   * checkpoint and the entry.
   */
  class CheckpointData
  {
  public:
    void
    set(const std::string &name, const std::vector<double> &values)
    {
      numbers[name] = values;
    }

    void
    set(const std::string &name, const double value)
    {
      numbers[name] = {value};
    }

    void
    set_text(const std::string &name, const std::string &text)
    {
      texts[name] = text;
    }

    /** The array `name`; with `size` > 0 it must have that many entries. */
    const std::vector<double> &
    get(const std::string &name, const std::size_t size = 0) const;

    /** A single number. */
    double
    value(const std::string &name) const
    {
      return get(name, 1)[0];
    }

    const std::string &
    text(const std::string &name) const;

    bool
    has(const std::string &name) const
    {
      return numbers.count(name) > 0 || texts.count(name) > 0;
    }

    /** Binary, with a leading tag; throws with the file's name on failure. */
    void
    write(const std::string &filename) const;

    void
    read(const std::string &filename);

  private:
    std::map<std::string, std::vector<double>> numbers;
    std::map<std::string, std::string>         texts;
    std::string                                source; // for messages
  };

  /**
   * The checkpoints of an output directory: `directory`/checkpoints/
   * step-NNNNNNN, each complete (a directory being written carries the
   * suffix .part until it is renamed).
   */
  namespace Checkpoints
  {
    /** The file in a checkpoint directory that holds the CheckpointData. */
    inline const char *data_file = "state.bin";
    /** The parameters of the run that wrote it. */
    inline const char *parameter_file = "parameters.prm";
    /** The prefix of the mesh files (a distributed mesh). */
    inline const char *mesh_file = "mesh";
    /** The size and CRC-32 of every other file, written last. */
    inline const char *checksum_file = "checksums";

    /**
     * First process, when every other file of the checkpoint in
     * `directory` is written: lists their sizes and checksums.
     */
    void
    write_checksums(const std::string &directory);

    /**
     * Before anything of `checkpoint` is read: every file its checksum
     * list names exists with that size and checksum; throws naming the
     * first that does not (or the missing list). With `only`, that file
     * alone (the parameters read before the rest).
     */
    void
    verify(const std::string &checkpoint, const std::string &only = "");

    /**
     * Throws unless `bytes` fit into the free space where `directory` is
     * (what a checkpoint needs, estimated before it is written: a full disk
     * in the middle of p4est's write aborts the program).
     */
    void
    check_free_space(const std::string &directory, const double bytes);

    /** Where the checkpoint of `step` goes, and its temporary name. */
    std::string
    directory(const std::string &output_directory, const unsigned int step);

    /**
     * First process: removes a temporary directory left by a stopped run
     * and creates `temporary` anew for the checkpoint `final`. Throws
     * naming it, and changes nothing, where either name is taken by a
     * directory with files this program does not write.
     */
    void
    create_temporary(const std::string &temporary, const std::string &final);

    /**
     * First process: renames the complete `temporary` to `final` (replacing
     * one of the same step) and removes all but the `keep` newest
     * checkpoints up to it, those of later steps (a run restarted from an
     * earlier checkpoint abandons them) and every other temporary
     * directory: only directories that hold nothing but checkpoint files.
     */
    void
    commit(const std::string &temporary,
           const std::string &final,
           const unsigned int keep);

    /**
     * The entries of two parameter files as ParameterHandler prints them
     * (ShortPRM) that differ, as 'Section/Entry: old -> new', leaving out
     * those whose name starts with one of `allowed`. An entry added to the
     * program after `old_text` was written counts there with the value
     * the older program had (Finite element/Polynomial degree: 1).
     */
    std::vector<std::string>
    changed_entries(const std::string              &old_text,
                    const std::string              &new_text,
                    const std::vector<std::string> &allowed);

    /**
     * A hash (hexadecimal) of the last up to 4096 bytes of the first `size`
     * bytes of `file`: a restart checks that it continues the file the
     * checkpoint was written with. Empty if the file cannot be read.
     */
    std::string
    tail_hash(const std::string &file, const std::uintmax_t size);

    /**
     * First process, restarting from `checkpoint`: removes the checkpoints
     * of later steps next to it (they continue a run the restart
     * abandons).
     */
    void
    remove_later(const std::string &checkpoint);

    /**
     * A new run: removes the checkpoints this program wrote in
     * `output_directory`/checkpoints (and the directory, if nothing else is
     * in it).
     */
    void
    remove_all_checkpoints(const std::string &output_directory);

    /**
     * `path` if it holds a checkpoint, else the newest complete checkpoint
     * under `path`/checkpoints (or `path` itself, a checkpoints directory),
     * as an absolute name; throws naming `path` if there is none.
     */
    std::string
    find(const std::string &path);
  } // namespace Checkpoints
} // namespace ContactDynamics

#endif
