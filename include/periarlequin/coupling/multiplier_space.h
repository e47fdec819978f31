#ifndef periarlequin_coupling_multiplier_space_h
#define periarlequin_coupling_multiplier_space_h

#include <periarlequin/coupling/interpolation_operator.h>
#include <periarlequin/coupling/transposed_rows.h>

#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace PeriArlequin
{
  using namespace dealii;

  /**
   * The lambda-mesh of eq. 40: where the multipliers live and H, H_IK = N^lambda_K(x_I), that
   * maps them to the PD nodes of the overlap. Multiplier vectors are distributed vectors
   * without ghosts, one entry per multiplier and component, each owned by one rank.
   */
  template <int dim>
  class MultiplierSpace
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    using Values     = typename InterpolationOperator<dim>::Values;

    virtual ~MultiplierSpace() = default;

    /** Shape a multiplier vector. */
    void
    initialize_vector(VectorType &lambda) const;

    /** p = H lambda at the overlap PD nodes (the rows of @p overlap). */
    virtual void
    apply_h(const VectorType &lambda, Values &p) = 0;

    /** y = H^T s for s at the overlap PD nodes: the constraint of eq. 38 tested by H. */
    virtual void
    apply_transpose_h(const Values &s, VectorType &y) = 0;

    /**
     * The diagonal of H^T (N W N^T + P) H, with W the FE DoF weights @p fe_weights (with
     * ghost values) and P the overlap PD nodes' weights @p pd_weights: with inverse masses,
     * the diagonal of A / dt (eq. 67).
     */
    virtual void
    diagonal_of_projection(const VectorType          &fe_weights,
                           const std::vector<double> &pd_weights,
                           VectorType                &diagonal) const = 0;

  protected:
    /** A space of @p n_owned multipliers on this rank. */
    void
    reinit_partitioner(const unsigned int n_owned, const MPI_Comm communicator);

    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
  };

  /** Strict coupling: a multiplier per PD node of the overlap and component, H = I. */
  template <int dim>
  class StrictMultiplierSpace : public MultiplierSpace<dim>
  {
  public:
    using typename MultiplierSpace<dim>::VectorType;
    using typename MultiplierSpace<dim>::Values;

    StrictMultiplierSpace(const InterpolationOperator<dim> &overlap, const MPI_Comm communicator);

    void
    apply_h(const VectorType &lambda, Values &p) override;
    void
    apply_transpose_h(const Values &s, VectorType &y) override;
    void
    diagonal_of_projection(const VectorType          &fe_weights,
                           const std::vector<double> &pd_weights,
                           VectorType                &diagonal) const override;

  private:
    const InterpolationOperator<dim> &overlap;
  };

  /**
   * Weak coupling: a multiplier per FE DoF whose shape function reaches a PD node of the
   * overlap, interpolated like the displacement: H = N on those DoFs.
   */
  template <int dim>
  class WeakMultiplierSpace : public MultiplierSpace<dim>
  {
  public:
    using typename MultiplierSpace<dim>::VectorType;
    using typename MultiplierSpace<dim>::Values;

    WeakMultiplierSpace(const InterpolationOperator<dim> &overlap, const FEZone<dim> &fe_zone);

    void
    apply_h(const VectorType &lambda, Values &p) override;
    void
    apply_transpose_h(const Values &s, VectorType &y) override;
    /**
     * With B = N^T N over the overlap (assembled once, FE pattern):
     * diag_m = sum_J B_mJ^2 W_J + sum_I N_Im^2 P_I.
     */
    void
    diagonal_of_projection(const VectorType          &fe_weights,
                           const std::vector<double> &pd_weights,
                           VectorType                &diagonal) const override;

  private:
    const InterpolationOperator<dim> &overlap;
    const FEZone<dim>                &fe_zone;
    /** Owned FE DoFs (local index) carrying a multiplier, in multiplier order. */
    std::vector<unsigned int> multiplier_dofs;
    VectorType                fe_scratch;
  };

  /**
   * Weak coupling on a lambda-mesh of its own: the Q1 hat functions of a Cartesian grid of
   * spacing H = k h_FE (k >= 1, h_FE the largest FE cell extent around the overlap) laid from
   * the lower corner of the overlap's PD nodes (or a fraction of H before it), a multiplier per
   * grid node whose hat reaches one of them. With H = 2 h_FE the constraint is blind to the waves
   * of 2 to 4 FE cells that the FE mesh carries but cannot propagate: in the overlap they are fine
   * scale, left to the damping, instead of being tied to an FE field that sends them back
   * (studies/wave_coupling/README.md).
   */
  template <int dim>
  class GridMultiplierSpace : public MultiplierSpace<dim>
  {
  public:
    using typename MultiplierSpace<dim>::VectorType;
    using typename MultiplierSpace<dim>::Values;

    /**
     * The grid of spacing @p spacing_in_cells (k >= 1) FE cells over the overlap nodes
     * @p positions (the rows of @p overlap), its nodes moved back by @p offset (in [0, 1))
     * of the spacing from their lower corner.
     */
    GridMultiplierSpace(const InterpolationOperator<dim> &overlap,
                        const FEZone<dim>                &fe_zone,
                        const std::vector<Point<dim>>    &positions,
                        const double                      spacing_in_cells,
                        const double                      offset);

    void
    apply_h(const VectorType &lambda, Values &p) override;
    void
    apply_transpose_h(const Values &s, VectorType &y) override;
    /**
     * Probed: A restricted to the multipliers of one colour (grid nodes whose indices agree
     * modulo a stride that keeps their reach apart) is diagonal, so applying the weighted
     * operator to the colour's indicator returns their diagonal entries.
     */
    void
    diagonal_of_projection(const VectorType          &fe_weights,
                           const std::vector<double> &pd_weights,
                           VectorType                &diagonal) const override;

  private:
    /** Hat weight of a grid node at an overlap node (local index of its first component). */
    struct Entry
    {
      unsigned int node;
      double       value;
    };

    void
    evaluate(const VectorType &lambda, Values &p) const;
    void
    evaluate_transpose(const Values &s, VectorType &y) const;

    const InterpolationOperator<dim> &overlap;
    const FEZone<dim>                &fe_zone;
    std::vector<unsigned int>         row_begin = {0};
    std::vector<Entry>                entries;
    /** H^T by columns, for the product on the threads. */
    TransposedRows<dim> transpose;
    /** Colour of each owned grid node (0 to stride^dim - 1). */
    std::vector<unsigned int> colours;
    unsigned int              n_colours = 1;
    /** Multipliers with the ghost entries that the owned overlap nodes reach. */
    mutable VectorType ghosted;
  };
} // namespace PeriArlequin

#endif
