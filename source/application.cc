#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <contact_dynamics/application.h>
#include <contact_dynamics/parallel.h>
#include <contact_dynamics/scenes/scene_registry.h>
#include <contact_dynamics/simulator.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace ContactDynamics
{
  namespace
  {
    void
    declare_dimension(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain) or 3. The "
                        "scenes in 3-D: " +
                          scene_names(3, ", ") + ".");
    }

    template <int dim>
    SceneLayout
    layout_from(ParameterHandler &prm)
    {
      Scene<dim> scene;
      scene.parse_parameters(prm);
      return scene.layout();
    }

    template <int dim>
    void
    run(ParameterHandler  &prm,
        const std::string &filename,
        std::ostream      &screen,
        const bool         validate_only)
    {
      // a run that stops destroys the simulator before the error leaves
      // here: its TimerOutput then has nothing to say about an uncaught
      // exception
      std::exception_ptr failure;
      {
        Simulator<dim> simulator(prm, screen);
        if (validate_only)
          {
            if (is_root(MPI_COMM_WORLD))
              screen << filename << ": the parameters are valid." << std::endl;
            return;
          }
        prm.enter_subsection("Output");
        const std::string directory = prm.get("Output directory");
        prm.leave_subsection();
        if (is_root(MPI_COMM_WORLD))
          {
            std::filesystem::create_directories(directory);
            std::ofstream used(directory + "/parameters.prm");
            prm.print_parameters(used, ParameterHandler::ShortPRM);
          }
        MPI_Barrier(MPI_COMM_WORLD);
        try
          {
            simulator.run();
          }
        catch (...)
          {
            failure = std::current_exception();
          }
      }
      if (failure)
        std::rethrow_exception(failure);
    }
  } // namespace

  unsigned int
  read_parameters(const std::string &filename, ParameterHandler &prm)
  {
    AssertThrow(std::ifstream(filename).good(),
                ExcMessage("Cannot open the parameter file '" + filename +
                           "'."));
    // First pass: only the dimension and the scene, to learn the bodies.
    ParameterHandler first;
    declare_dimension(first);
    Scene<2>::declare_parameters(first);
    first.parse_input(filename, "", true);
    const unsigned int dim = first.get_integer("Dimension");
    const SceneLayout  layout =
      (dim == 2 ? layout_from<2>(first) : layout_from<3>(first));

    declare_dimension(prm);
    if (dim == 2)
      Simulator<2>::declare_parameters(prm, layout);
    else
      Simulator<3>::declare_parameters(prm, layout);
    prm.parse_input(filename);
    return dim;
  }

  void
  run_parameter_file(const std::string &filename,
                     std::ostream      &screen,
                     const bool         validate_only)
  {
    ParameterHandler   prm;
    const unsigned int dim = read_parameters(filename, prm);
    if (dim == 2)
      run<2>(prm, filename, screen, validate_only);
    else
      run<3>(prm, filename, screen, validate_only);
  }

  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "Usage:\n"
          << "  contact-dynamics FILE.prm                run a simulation\n"
          << "  contact-dynamics --validate FILE.prm     check a parameter "
             "file without running it\n"
          << "  contact-dynamics --print-parameters [FILE.prm]\n"
          << "                                           print every "
             "parameter, documented, with\n"
          << "                                           the defaults (or "
             "the values of FILE.prm)\n"
          << "  contact-dynamics --help\n";
    }

    void
    print_parameters(const std::string &filename, std::ostream &out)
    {
      ParameterHandler prm;
      if (!filename.empty())
        read_parameters(filename, prm);
      else
        {
          ParameterHandler first;
          declare_dimension(first);
          Scene<2>::declare_parameters(first);
          declare_dimension(prm);
          Simulator<2>::declare_parameters(prm, layout_from<2>(first));
        }
      prm.print_parameters(out, ParameterHandler::PRM);
    }
  } // namespace

  int
  run_command_line(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool root = (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    try
      {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.empty() || args[0] == "--help" || args[0] == "-h")
          {
            if (root)
              print_usage(std::cout);
            return args.empty() ? 1 : 0;
          }
        if (args[0] == "--print-parameters")
          {
            AssertThrow(args.size() <= 2,
                        ExcMessage("--print-parameters takes at most one "
                                   "parameter file."));
            if (root)
              print_parameters(args.size() == 2 ? args[1] : "", std::cout);
            return 0;
          }
        if (args[0] == "--validate")
          {
            AssertThrow(args.size() == 2,
                        ExcMessage("--validate takes exactly one parameter "
                                   "file."));
            run_parameter_file(args[1], std::cout, true);
            return 0;
          }
        AssertThrow(args.size() == 1 && args[0].rfind("--", 0) != 0,
                    ExcMessage("Unknown command line '" + args[0] +
                               "'. Run 'contact-dynamics --help'."));
        run_parameter_file(args[0], std::cout, false);
        return 0;
      }
    catch (const ExceptionBase &e)
      {
        if (root)
          {
            std::cerr << "\nError: ";
            e.print_info(std::cerr);
            std::cerr << std::endl;
          }
      }
    catch (const std::exception &e)
      {
        if (root)
          std::cerr << "\nError: " << e.what() << std::endl;
      }
    return 1;
  }
} // namespace ContactDynamics
