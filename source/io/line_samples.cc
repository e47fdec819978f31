#include <periarlequin/io/line_samples.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace PeriArlequin
{
  template <int dim>
  LineSamples<dim>::LineSamples(const Point<dim>         &a,
                                const Point<dim>         &b,
                                const Parameters::Output &parameters,
                                const double              lattice_spacing,
                                const MPI_Comm            communicator)
    : a(a)
    , b(b)
    , parameters(parameters)
    , lattice_spacing(lattice_spacing)
    , communicator(communicator)
  {}

  template <int dim>
  void
  LineSamples<dim>::write(const unsigned int step,
                          const FEZone<dim> *fe_zone,
                          const PDZone<dim> *pd_zone) const
  {
    const Tensor<1, dim> e        = b - a;
    const auto           distance = [&](const Point<dim> &x) {
      const double s = std::clamp((x - a) * e / (e * e), 0., 1.);
      return (x - (a + s * e)).norm();
    };
    // Rows: zone (0 FE, 1 PD), position, displacement, velocity.
    std::vector<double> rows;
    const auto          add_row = [&](const double          zone,
                             const Point<dim>     &x,
                             const Tensor<1, dim> &u,
                             const Tensor<1, dim> &v) {
      rows.push_back(zone);
      for (unsigned int d = 0; d < dim; ++d)
        rows.push_back(x[d]);
      for (unsigned int d = 0; d < dim; ++d)
        rows.push_back(u[d]);
      for (unsigned int d = 0; d < dim; ++d)
        rows.push_back(v[d]);
    };
    if (fe_zone)
      {
        std::vector<unsigned int> dofs, components;
        std::vector<Point<dim>>   points;
        fe_zone->support_points(dofs, points, components);
        const double tolerance = 1e-9 * e.norm();
        std::map<std::vector<double>, std::pair<Tensor<1, dim>, Tensor<1, dim>>> nodes;
        for (unsigned int k = 0; k < dofs.size(); ++k)
          if (distance(points[k]) <= tolerance)
            {
              auto &node = nodes[std::vector<double>(points[k].begin_raw(), points[k].end_raw())];
              node.first[components[k]]  = fe_zone->get_state().displacement.local_element(dofs[k]);
              node.second[components[k]] = fe_zone->get_state().velocity.local_element(dofs[k]);
            }
        for (const auto &[x, values] : nodes)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = x[d];
            add_row(0, p, values.first, values.second);
          }
      }
    if (pd_zone)
      for (unsigned int i = 0; i < pd_zone->n_owned_particles(); ++i)
        if (distance(pd_zone->reference_positions()[i]) <= 0.5 * lattice_spacing * (1. + 1e-9))
          add_row(1,
                  pd_zone->reference_positions()[i],
                  pd_zone->get_state().displacements()[i],
                  pd_zone->get_state().velocities()[i]);

    const auto all = Utilities::MPI::gather(communicator, rows, 0);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    const unsigned int               width = 1 + 3 * dim;
    std::vector<std::vector<double>> sorted;
    for (const auto &part : all)
      for (unsigned int r = 0; r + width <= part.size(); r += width)
        sorted.emplace_back(part.begin() + r, part.begin() + r + width);
    // by zone, then position: the same file whatever the partition
    std::sort(sorted.begin(), sorted.end(), [](const auto &left, const auto &right) {
      return std::lexicographical_compare(left.begin(),
                                          left.begin() + 1 + dim,
                                          right.begin(),
                                          right.begin() + 1 + dim);
    });
    std::ostringstream name;
    name << parameters.directory << "/" << parameters.base_name << "_line_" << std::setw(6)
         << std::setfill('0') << step << ".csv";
    std::ofstream out(name.str());
    const char   *axes[] = {"x", "y", "z"};
    out << "zone";
    for (unsigned int d = 0; d < dim; ++d)
      out << "," << axes[d];
    for (unsigned int d = 0; d < dim; ++d)
      out << ",u_" << axes[d];
    for (unsigned int d = 0; d < dim; ++d)
      out << ",v_" << axes[d];
    out << "\n" << std::setprecision(12);
    for (const auto &row : sorted)
      {
        out << (row[0] == 0 ? "fe" : "pd");
        for (unsigned int k = 1; k < width; ++k)
          out << "," << row[k];
        out << "\n";
      }
  }

  template class LineSamples<2>;
  template class LineSamples<3>;
} // namespace PeriArlequin
