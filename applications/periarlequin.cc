/**
 * periarlequin: run a case described by a deal.II parameter file.
 *
 *   periarlequin input.prm                 run (serial, or under mpirun)
 *   periarlequin --check input.prm         parse and validate: set the case up (mesh, zones,
 *                                          coupling, stable step) without running or writing
 *   periarlequin --print-parameters [2|3]  print every parameter with default and documentation
 *   periarlequin --print-parameters input.prm
 *                                          print the case as read: every entry's value, the
 *                                          files it includes resolved (a study's variants)
 */
#include <periarlequin/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
  using namespace dealii;

  /** Read only "Dimension" from the file, skipping everything else. */
  unsigned int
  read_dimension(const std::string &file_name)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    prm.parse_input(file_name, "", true);
    return prm.get_integer("Dimension");
  }

  template <int dim>
  void
  run(const std::string &file_name, const bool check_only)
  {
    ParameterHandler prm;
    PeriArlequin::Simulator<dim>::declare_parameters(prm);
    prm.parse_input(file_name);
    // A relative Geometry/Mesh file is read from the parameter file's directory.
    prm.enter_subsection("Geometry");
    const std::filesystem::path mesh_file = prm.get("Mesh file");
    if (!mesh_file.empty() && mesh_file.is_relative())
      prm.set(
        "Mesh file",
        (std::filesystem::path(file_name).parent_path() / mesh_file).lexically_normal().string());
    prm.leave_subsection();
    PeriArlequin::Simulator<dim> simulator(prm, MPI_COMM_WORLD);
    if (check_only)
      {
        simulator.setup();
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << "Parameters of '" << file_name << "' are valid." << std::endl;
        return;
      }
    simulator.run();
  }

  /** Every parameter with its default and documentation, or, given a file, the case it holds. */
  template <int dim>
  void
  print_parameters(const std::string &file_name)
  {
    ParameterHandler prm;
    PeriArlequin::Simulator<dim>::declare_parameters(prm);
    prm.set("Dimension", std::to_string(dim));
    if (file_name.empty())
      prm.print_parameters(std::cout, ParameterHandler::PRM);
    else
      {
        prm.parse_input(file_name);
        prm.print_parameters(std::cout,
                             ParameterHandler::OutputStyle(ParameterHandler::PRM |
                                                           ParameterHandler::Short));
      }
  }

  /**
   * After an error: on several ranks, end them all, since a rank whose error was its own would
   * otherwise leave the others waiting in their next collective call.
   */
  int
  fail()
  {
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace

int
main(int argc, char **argv)
{
  // Threads per rank: the cores of a node shared among its ranks, at most DEAL_II_NUM_THREADS.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, numbers::invalid_unsigned_int);
  try
    {
      const bool        root  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const std::string first = argc > 1 ? argv[1] : "";
      if (first == "--print-parameters")
        {
          const std::string d       = argc > 2 ? argv[2] : "2";
          const bool        is_file = d != "2" && d != "3";
          if (is_file && !std::ifstream(d))
            {
              std::cerr << "--print-parameters takes the dimension 2 or 3 or a parameter file, "
                           "not '"
                        << d << "'.\n";
              return 1;
            }
          const std::string file = is_file ? d : "";
          if (root)
            ((is_file ? read_dimension(file) : std::stoi(d)) == 2) ? print_parameters<2>(file) :
                                                                     print_parameters<3>(file);
          return 0;
        }
      const bool        check_only = first == "--check";
      const std::string file       = check_only && argc == 3 ? argv[2] : first;
      if (argc != (check_only ? 3 : 2) || file.empty() || file[0] == '-')
        {
          if (root)
            std::cerr << "Usage: periarlequin input.prm\n"
                         "       periarlequin --check input.prm\n"
                         "       periarlequin --print-parameters [2|3 | input.prm]\n";
          return 1;
        }
      if (!std::ifstream(file))
        {
          if (root)
            std::cerr << "Error: cannot open the parameter file '" << file << "'.\n";
          return 1;
        }
      if (read_dimension(file) == 2)
        run<2>(file, check_only);
      else
        run<3>(file, check_only);
    }
  catch (const ExceptionBase &error)
    {
      // The message alone: input errors are for users, not a stack trace.
      std::cerr << "\nError:\n";
      error.print_info(std::cerr);
      return fail();
    }
  catch (const std::exception &error)
    {
      std::cerr << "\nError: " << error.what() << std::endl;
      return fail();
    }
  return 0;
}
