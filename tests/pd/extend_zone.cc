// A PD zone extended between steps (PDZone::extend) is the zone that set-up would have built
// on the larger region. Zone A (left part of a plate) starts with a smooth displacement plus
// a jump across y = H/2 near the left edge that breaks the bonds crossing it; it is then
// extended by a block B on its right (more than a horizon away from the broken bonds) whose
// new particles take the same displacement field. A second zone is built directly on A u B
// with the same initial field. Compared, independent of the partition and of the local
// numbering:
// - particle, bond and broken-bond counts (exact): the broken bonds survive the rebuild, the
//   new bonds between A and B are intact, and the particles added are those of B;
// - internal forces particle by particle (matched by id) and strain energy, relative to the
//   largest force and to the energy: 1e-12, round-off of bond sums taken in another order
//   (about 100 bonds of relative rounding 1e-16 each);
// - kinetic energy (an initial velocity field too) at the start, 1e-12, and after 40 further
//   velocity-Verlet steps of both zones, 1e-10: the same round-off grown by a stable
//   integration over 40 steps.
// On 2 ranks the extended zone keeps the partition made for A, so new particles, their
// ghosts and bonds cross rank boundaries that the direct build does not have.

#include <deal.II/base/mpi.templates.h>

#include <tuple>

#include "../tests.h"

using namespace PeriArlequinTests;

namespace
{
  /** Region text of the box [lower, upper] in dim dimensions (extra axes span [0, 0.005]). */
  template <int dim>
  std::string
  box(const double x0, const double x1)
  {
    return dim == 2 ? std::to_string(x0) + ", 0 : " + std::to_string(x1) + ", 0.01" :
                      std::to_string(x0) + ", 0, 0 : " + std::to_string(x1) + ", 0.01, 0.005";
  }

  template <int dim>
  std::string
  parameters(const std::string &region)
  {
    std::ostringstream prm;
    prm << "set Dimension = " << dim << "\n"
        << "subsection Geometry\n  set Lower corner = " << (dim == 2 ? "0, 0" : "0, 0, 0")
        << "\n  set Upper corner = " << (dim == 2 ? "0.02, 0.01" : "0.02, 0.01, 0.005")
        << "\n  set Subdivisions = " << (dim == 2 ? "8, 4" : "8, 4, 2") << "\nend\n"
        << "subsection Material\n  set Young's modulus = 69e9\n  set Poisson's ratio = 0.3\nend\n"
        << "subsection Peridynamics\n  set Region = " << region
        << "\n  set Lattice spacing = 5e-4\n  set Fracture = true\n"
        << "  set Critical energy release rate = 100\nend\n"
        << "subsection Initial conditions\nsubsection function\n  subsection Displacement\n"
        << "    set Function expression = 1e-3*x*x; 2e-3*x*y + ((x < 0.004 && y > 0.005) ? "
           "5e-5 : 0)"
        << (dim == 3 ? "; 1e-3*z*x" : "") << "\n  end\n  subsection Velocity\n"
        << "    set Function expression = 0.1*y; -0.2*x" << (dim == 3 ? "; 0.1*x" : "")
        << "\n  end\nend\nend\n"
        << "subsection Time\n  set Time step = 2e-8\n  set Stability estimate iterations = 5\n"
        << "end\n"
        << quiet_output();
    return prm.str();
  }

  /** The same fields as the parameter file's initial displacement and velocity. */
  template <int dim>
  std::pair<Tensor<1, dim>, Tensor<1, dim>>
  initial_state(const Point<dim> &p)
  {
    Tensor<1, dim> u, v;
    u[0] = 1e-3 * p[0] * p[0];
    u[1] = 2e-3 * p[0] * p[1] + ((p[0] < 0.004 && p[1] > 0.005) ? 5e-5 : 0);
    v[0] = 0.1 * p[1];
    v[1] = -0.2 * p[0];
    if (dim == 3)
      {
        u[2] = 1e-3 * p[2] * p[0];
        v[2] = 0.1 * p[0];
      }
    return {u, v};
  }

  /** Internal force density of every particle of the zone, by particle id, on every rank. */
  template <int dim>
  std::map<types::particle_index, Tensor<1, dim>>
  forces_by_id(const PeriArlequin::PDZone<dim> &pd)
  {
    std::vector<std::pair<types::particle_index, Tensor<1, dim>>> owned;
    for (unsigned int i = 0; i < pd.n_owned_particles(); ++i)
      owned.emplace_back(pd.particle_ids()[i], pd.force_densities()[i]);
    std::map<types::particle_index, Tensor<1, dim>> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, owned))
      all.insert(part.begin(), part.end());
    return all;
  }

  template <int dim>
  void
  step(PeriArlequin::PDZone<dim> &pd, const double dt, const double time)
  {
    pd.predict(dt);
    pd.impose_prescribed_motion(time);
    pd.compute_forces(time);
    pd.compute_accelerations(time);
    pd.correct(dt);
  }
} // namespace

template <int dim>
void
extend_zone()
{
  const std::string title    = std::to_string(dim) + "D ";
  auto              extended = make_simulator<dim>(parameters<dim>(box<dim>(0, 0.01)));
  extended->setup();
  auto &pd = *extended->get_pd_zone();
  pd.compute_forces(0.);
  pd.compute_accelerations(0.);
  const auto n_a         = pd.n_global_particles();
  const auto broken_in_a = pd.n_global_broken_bonds();
  AssertThrow(broken_in_a > 0, ExcMessage("the displacement jump broke no bond"));

  const auto                previous = pd.extend([](const Point<dim> &p) { return p[0] < 0.015; });
  std::vector<unsigned int> added;
  for (unsigned int i = 0; i < previous.size(); ++i)
    if (previous[i] == numbers::invalid_unsigned_int)
      added.push_back(i);
  // Before any new force evaluation (which would break the bonds across the jump again).
  check(title + "broken bond ends kept", pd.n_global_broken_bonds(), broken_in_a, 0);
  for (const unsigned int i : added)
    {
      const auto [displacement, velocity] = initial_state(pd.reference_positions()[i]);
      pd.set_displacement(i, displacement);
      pd.set_velocity_and_acceleration(i, velocity, pd.get_state().accelerations()[i]);
    }
  pd.update_ghost_displacements();
  pd.compute_forces(0.);
  pd.compute_accelerations(0.);

  auto direct = make_simulator<dim>(parameters<dim>(box<dim>(0, 0.015)));
  direct->setup();
  auto &reference = *direct->get_pd_zone();
  reference.compute_forces(0.);
  reference.compute_accelerations(0.);

  const double n_added = Utilities::MPI::sum(static_cast<double>(added.size()), MPI_COMM_WORLD);
  check(title + "particles added", n_added, reference.n_global_particles() - n_a, 0);
  check(title + "particles", pd.n_global_particles(), reference.n_global_particles(), 0);
  check(title + "bond ends", pd.n_global_bonds(), reference.n_global_bonds(), 0);
  check(title + "broken bond ends",
        pd.n_global_broken_bonds(),
        reference.n_global_broken_bonds(),
        0);

  const auto forces = forces_by_id(pd), reference_forces = forces_by_id(reference);
  AssertThrow(forces.size() == reference_forces.size(), ExcMessage("different particle sets"));
  double largest = 0, difference = 0;
  for (const auto &[id, f] : reference_forces)
    {
      AssertThrow(forces.count(id), ExcMessage("particle " + std::to_string(id) + " missing"));
      largest    = std::max(largest, f.norm());
      difference = std::max(difference, (forces.at(id) - f).norm());
    }
  check_below(title + "max |f - f_direct| / max |f_direct|", difference / largest, 1e-12);
  check_below(title + "|W - W_direct| / W_direct",
              std::abs(pd.strain_energy() / reference.strain_energy() - 1),
              1e-12);
  check_below(title + "|K - K_direct| / K_direct at the start",
              std::abs(pd.kinetic_energy() / reference.kinetic_energy() - 1),
              1e-12);

  const double dt = 2e-8;
  for (unsigned int n = 1; n <= 40; ++n)
    {
      step(pd, dt, n * dt);
      step(reference, dt, n * dt);
    }
  check_below(title + "|K - K_direct| / K_direct after 40 steps",
              std::abs(pd.kinetic_energy() / reference.kinetic_energy() - 1),
              1e-10);
}

int
main(int argc, char **argv)
{
  return run_test(argc, argv, [] {
    extend_zone<2>();
    extend_zone<3>();
  });
}
