// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FFT_FFT_OPERATOR_H
#define PDFEM_FFT_FFT_OPERATOR_H

#include <pdfem/fft/operator.h>

#include <memory>

#include <mpi.h>

namespace pdfem
{
  namespace FFT
  {
    /// How FFTW chooses its algorithms (FFTW_ESTIMATE or FFTW_MEASURE).
    enum class Planning
    {
      /// Heuristic plans: made at once, the same on every run.
      estimate,
      /// Timed plans: seconds to make (per size and thread count) and
      /// faster; the algorithm may change between runs (round-off only).
      measure
    };

    /// Options of FftOperator.
    struct FftOptions
    {
      /// Threads of FFTW's plans (fftw3_threads) and of the pointwise
      /// loops (per rank).
      unsigned int threads  = 1;
      Planning     planning = Planning::estimate;
      /**
       * The ranks that share the box. MPI_COMM_SELF (or any communicator
       * of one rank): every field is the whole grid, serial FFTW plans.
       * Several ranks: the box is split into slabs of whole planes along
       * the slowest index (local_slab(), FFTW's MPI layout, fftw3-mpi
       * plans); each rank holds and takes its slab only. The constructor,
       * set_masks(), apply(), dilatation(), energy_density(), damage() and
       * apply_periodic_inverse() are then collective (all ranks call them,
       * in the same order); the accessors are not.
       */
      MPI_Comm communicator = MPI_COMM_SELF;
      /**
       * Whether the fields that depend on the masks only are kept from
       * set_masks() to the evaluations (true) or recomputed in each
       * (false, the lean setting; theory.md §14.3). Kept: P_ij = [C_ij beta]
       * of the linear bond-based model (dim (dim + 1) / 2 fields, 48 bytes
       * per node in 3D), of the nonlinear one also q_i = [a_i beta] and
       * p = [c beta] (80 bytes), and of LPS [g_i beta] (dim fields) with
       * the combined (1/m) [K_ij beta] + [K_ij (beta/m)] (72 bytes per node
       * in 3D), each at the layer nodes only (n_layer_nodes()). Recomputing
       * takes per force evaluation in 3D 13 transforms
       * instead of 6 (linear bond based), 55 instead of 35 (nonlinear bond
       * based) and 32 instead of 14 (LPS); the results are the same to
       * round-off.
       */
      bool keep_mask_fields = true;
    };

    /**
     * The slab of @p grid this rank holds in an FftOperator on
     * @p communicator (the whole grid for one rank): the same as
     * FftOperator::slab(), known before the operator is made (FFTW's
     * blocks of ceil(n_0 / ranks) planes; no communication). Ranks after
     * the last plane hold none.
     */
    template <int dim>
    Slab
    local_slab(const Grid<dim> &grid, MPI_Comm communicator);

    /**
     * The operators of Operator<dim> by the fast convolution-based method
     * (FCBM, specs/002): every sum over the horizon is written as sums of
     * a(x) [k * b](x), a and b nodal fields (products of u, beta, theta,
     * 1/m), k a kernel of xi, and each convolution is evaluated as a
     * circular convolution by real-to-complex FFTs (FFTW). Kernels are
     * transformed once (their spectra are real for even kernels and
     * imaginary for odd ones, so one real number per mode is kept, and only
     * on the modes with k_d <= n_d / 2: each kernel is even or odd in
     * every direction, theory.md §14.3), the two
     * plans (r2c and c2r) are made once and reused for every transform,
     * and sums over a kernel index are taken in Fourier space so that one
     * inverse transform serves a whole sum.
     *
     * Forms evaluated (beta = chi_B lambda, [k b](x) = sum_x' k(x' - x)
     * b(x') Delta V, u' = u(x')):
     *
     * - linear bond based, specs/002 eqs. 46/101:
     *   L_i = beta ([C_ij (beta u_j)] - u_j [C_ij beta]);
     * - nonlinear bond based, the corrected form of specs/002 §1.3 (the
     *   printed eqs. 26/59 are wrong, §7 E1), with a = c xi,
     *   c = alpha omega / |xi|^2;
     * - LPS, the variable-m form of specs/002 §1.4 (signs as corrected in
     *   §7 E2-E4, dilatation kernel g = omega xi as in E3).
     *
     * Per evaluation (3D): linear bond based 3 forward + 3 inverse FFTs,
     * LPS 7 + 7, nonlinear bond based 13 + 22. The transforms are in place
     * (a work spectrum's memory holds the real field before and after),
     * so no real buffer is kept beside the work spectra. FFTW
     * headers are kept out of this header (pimpl).
     *
     * MPI (FftOptions::communicator with several ranks): each rank holds
     * the Slab slab() of the box, whole planes of the slowest index, and
     * every field argument (u, force, theta, W, d, the masks, r, z) and
     * weighted_volume() hold that slab only: N = slab().n_nodes() values
     * per component, component c of box node slab().begin + k at c N + k.
     * The kernels are sampled on the slab, the Fourier-space work is done
     * on the rank's modes in FFTW's transposed layout (no transpose back),
     * and every result equals the one-rank result to round-off. The
     * memory per rank falls with the rank count (the masks, fields, kernel
     * spectra and the periodic inverse's symbol are O(N / ranks)).
     */
    template <int dim>
    class FftOperator : public Operator<dim>
    {
    public:
      /// Samples and transforms the kernels, makes the plans and sets the
      /// masks to 1 (a periodic body).
      FftOperator(const Grid<dim>  &grid,
                  const Material   &material,
                  const FftOptions &options = FftOptions());

      ~FftOperator() override;

      void
      set_masks(const std::vector<double> &body,
                const std::vector<double> &integrity) override;

      void
      apply(const std::vector<double> &u, std::vector<double> &force) override;

      void
      dilatation(const std::vector<double> &u,
                 std::vector<double>       &theta) override;

      void
      energy_density(const std::vector<double> &u,
                     std::vector<double>       &W) override;

      void
      damage(std::vector<double> &d,
             DamageNormalisation  normalisation) override;

      const std::vector<double> &
      weighted_volume() const override;

      /// bytes() / slab().n_nodes() (bytes() for a rank without nodes).
      double
      bytes_per_node() const override;

      /**
       * The bytes this rank holds: kernels, mask fields and work space at
       * FFTW's local allocation sizes (the caller's fields not included).
       */
      double
      bytes() const;

      /**
       * The nodes of this rank at which the kept mask fields are stored
       * (0 where they are recomputed, FftOptions::keep_mask_fields): the
       * body nodes with a node of beta != 1 within the fields' reach, one
       * horizon (LPS: the node itself and two horizons; theory.md §14.3).
       * At the other body nodes the fields equal their values in an
       * unbounded intact body, the sums of their kernels over the horizon,
       * and are not stored.
       */
      std::size_t
      n_layer_nodes() const;

      /// The part of the box this rank holds (the whole grid on one rank).
      const Slab &
      slab() const;

      /**
       * z = G^-1 r with G the operator -L of this material on the periodic
       * box with every mask 1 (a translation-invariant operator: its
       * Fourier symbol G^(kappa) is a real symmetric dim x dim matrix per
       * mode, the stencil being even),
       * the mode kappa = 0 (the rigid translations, where G^ = 0) replaced
       * by s I, s the mean eigenvalue of the lowest nonzero mode. The
       * inverse of the operator of an unbounded body: a preconditioner for
       * the masked operator of a bounded one (Krylov solves of statics).
       * The symbol is made at the first call (dim evaluations of L on unit
       * impulses, dim (dim + 1) / 2 forward FFTs) and its inverse kept
       * (dim (dim + 1) / 2 reals per mode of this rank: 24 bytes per box
       * node in 3D, 12 in 2D); each call costs dim forward and dim inverse
       * FFTs. @p r and @p z are laid out as the displacements of apply().
       */
      void
      apply_periodic_inverse(const std::vector<double> &r,
                             std::vector<double>       &z);

      /// The number of forward and inverse FFTs since construction (each
      /// distributed transform counted once).
      std::size_t
      n_transforms() const;

    private:
      struct Impl;
      std::unique_ptr<Impl> impl;
    };
  } // namespace FFT
} // namespace pdfem

#endif
