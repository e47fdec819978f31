// periarlequin-wave-reflection: the reflection and transmission of a wave packet at an
// Arlequin overlap (PeriArlequin::WaveReflection), for the absorption study
// (studies/wave_coupling/run_reflection.sh). Reads the subsection "Wave reflection" of a parameter
// file and prints one CSV row: wavelength / h, h / dx, overlap cells, R, T, time [s].

#include <periarlequin/postprocess/wave_reflection.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <iomanip>
#include <iostream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      if (argc != 2)
        {
          std::cerr << "Usage: periarlequin-wave-reflection input.prm" << std::endl;
          return 1;
        }
      dealii::ParameterHandler prm;
      PeriArlequin::WaveReflection::declare_parameters(prm);
      prm.parse_input(argv[1]);
      PeriArlequin::WaveReflection study;
      study.parse_parameters(prm);
      const auto result = study.measure(MPI_COMM_WORLD);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << std::setprecision(6) << study.wavelength << "," << study.size_ratio << ","
                  << study.overlap_cells << "," << result.reflected << "," << result.transmitted
                  << "," << result.time << std::endl;
    }
  catch (const dealii::ExceptionBase &error)
    {
      // The message alone: input errors are for users, not a stack trace.
      std::cerr << "\nError:\n";
      error.print_info(std::cerr);
      return 1;
    }
  catch (const std::exception &error)
    {
      std::cerr << "\nError: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
