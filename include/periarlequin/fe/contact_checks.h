#ifndef periarlequin_fe_contact_checks_h
#define periarlequin_fe_contact_checks_h

#include <periarlequin/base/parameters.h>
#include <periarlequin/fe/fe_zone.h>

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <sstream>
#include <string>

// The input checks and the face geometry the contact models share.
namespace PeriArlequin
{
  namespace internal
  {
    /** A set of ids as a parameter list. */
    inline std::string
    prm_list(const std::set<unsigned int> &ids)
    {
      std::string text;
      for (const unsigned int id : ids)
        text += (text.empty() ? "" : ", ") + std::to_string(id);
      return text;
    }

    /** Refuse boundary ids the mesh does not have, naming @p parameter. */
    template <int dim>
    void
    check_boundary_ids(const FEZone<dim>            &zone,
                       const std::set<unsigned int> &ids,
                       const std::string            &parameter)
    {
      const auto present = zone.get_dof_handler().get_triangulation().get_boundary_ids();
      for (const unsigned int id : ids)
        if (std::find(present.begin(), present.end(), id) == present.end())
          {
            std::ostringstream allowed;
            allowed << "boundary ids the mesh has (";
            for (unsigned int k = 0; k < present.size(); ++k)
              allowed << (k > 0 ? ", " : "") << present[k];
            allowed << "; a box has 0/1 on its x faces, 2/3 on y, 4/5 on z)";
            throw_invalid_parameter(parameter, std::to_string(id), allowed.str());
          }
    }

    /** Contact acts on vertices: FE_Q(1)^dim with lumped masses. */
    template <int dim>
    void
    check_linear_elements(const FEZone<dim> &zone, const std::string &model)
    {
      for (const auto &cell : zone.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
          {
            AssertThrow(cell->get_fe().degree == 1,
                        ExcMessage("Invalid input: 'Contact/Model' = " + model +
                                   " needs 'Finite elements/Polynomial degree' = 1 (lumped "
                                   "vertex masses)."));
            return;
          }
    }
    /**
     * Positions in lexicographic order (the last coordinate first), to sort nodes the same
     * on every partition.
     */
    template <int dim>
    bool
    position_before(const Point<dim> &a, const Point<dim> &b)
    {
      for (int d = dim - 1; d >= 0; --d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    }

    /** The shape values of a Q1 face (2 or 4 vertices, deal.II's order) at @p xi. */
    template <int dim>
    inline std::array<double, GeometryInfo<dim>::vertices_per_face>
    face_shape_values(const std::array<double, 2> &xi)
    {
      std::array<double, GeometryInfo<dim>::vertices_per_face> N;
      if constexpr (dim == 2)
        N = {{1 - xi[0], xi[0]}};
      else
        N = {{(1 - xi[0]) * (1 - xi[1]), xi[0] * (1 - xi[1]), (1 - xi[0]) * xi[1], xi[0] * xi[1]}};
      return N;
    }

    /**
     * The closest point of a Q1 face (@p x its vertices) to @p p: its face coordinates,
     * found by Gauss-Newton (exact in one step on a parallelogram), and the face's unit
     * normal there, oriented along @p outward.
     */
    template <int dim, typename Vertices>
    std::pair<std::array<double, 2>, Tensor<1, dim>>
    project_onto_face(const Vertices &x, const Point<dim> &p, const Tensor<1, dim> &outward)
    {
      std::array<double, 2>         xi = {{0.5, 0.5}};
      std::array<Tensor<1, dim>, 2> tangent;
      for (unsigned int iteration = 0; iteration < 20; ++iteration)
        {
          Point<dim> position;
          const auto N = face_shape_values<dim>(xi);
          for (unsigned int j = 0; j < x.size(); ++j)
            position += N[j] * Tensor<1, dim>(x[j]);
          if constexpr (dim == 2)
            tangent[0] = x[1] - x[0];
          else
            {
              tangent[0] = (1 - xi[1]) * (x[1] - x[0]) + xi[1] * (x[3] - x[2]);
              tangent[1] = (1 - xi[0]) * (x[2] - x[0]) + xi[0] * (x[3] - x[1]);
            }
          const Tensor<1, dim>  r    = p - position;
          std::array<double, 2> step = {{0, 0}};
          if constexpr (dim == 2)
            step[0] = (r * tangent[0]) / (tangent[0] * tangent[0]);
          else
            {
              const double a = tangent[0] * tangent[0], b = tangent[0] * tangent[1],
                           c = tangent[1] * tangent[1], det = a * c - b * b;
              const double r0 = r * tangent[0], r1 = r * tangent[1];
              step[0] = (c * r0 - b * r1) / det;
              step[1] = (a * r1 - b * r0) / det;
            }
          xi[0] += step[0];
          xi[1] += step[1];
          if (std::abs(step[0]) + std::abs(step[1]) < 1e-14)
            break;
        }
      Tensor<1, dim> normal;
      if constexpr (dim == 2)
        normal = Tensor<1, dim>({tangent[0][1], -tangent[0][0]});
      else
        normal = cross_product_3d(tangent[0], tangent[1]);
      normal /= normal.norm();
      if (normal * outward < 0)
        normal *= -1;
      return {xi, normal};
    }

    /** Where a point lies with respect to a Q1 face: the foot's shape values, the face's unit
     * outward normal there and the point's distance along it [m]. */
    template <int dim>
    struct FaceFoot
    {
      std::array<double, GeometryInfo<dim>::vertices_per_face> weights;
      Tensor<1, dim>                                           normal;
      double                                                   distance = 0;
    };

    /**
     * The foot of @p p on the face with vertices @p x (project_onto_face()), or nothing if it
     * falls outside the face.
     */
    template <int dim, typename Vertices>
    std::optional<FaceFoot<dim>>
    foot_on_face(const Vertices &x, const Point<dim> &p, const Tensor<1, dim> &outward)
    {
      const auto [xi, normal] = project_onto_face(x, p, outward);
      const double tolerance  = 1e-10;
      if (xi[0] < -tolerance || xi[0] > 1 + tolerance ||
          (dim == 3 && (xi[1] < -tolerance || xi[1] > 1 + tolerance)))
        return std::nullopt;
      FaceFoot<dim> foot;
      foot.weights = face_shape_values<dim>(xi);
      foot.normal  = normal;
      Point<dim> at;
      for (unsigned int j = 0; j < foot.weights.size(); ++j)
        at += foot.weights[j] * Tensor<1, dim>(x[j]);
      foot.distance = (p - at) * normal;
      return foot;
    }
  } // namespace internal
} // namespace PeriArlequin

#endif
