#include "techniques/mass_spring/spring_solvers.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>

namespace tb::mass_spring {

template <class Real>
SpringSolver<Real>::SpringSolver(const SpringSystem& system, const SolverSettings& settings)
    : system_(system), settings_(settings) {
  for (const Spring& spring : system.springs) {
    a_.push_back(spring.a);
    b_.push_back(spring.b);
    rest_.push_back(Real(spring.rest_m));
    weight_.push_back(Real(spring.weight));
  }
  end_start_ = system.end_start;
  for (const SpringEnd& end : system.ends) {
    end_other_.push_back(end.other);
    end_rest_.push_back(Real(end.rest_m));
    end_weight_.push_back(Real(end.weight));
  }
  for (size_t v = 0; v < system.vertex_count; ++v) {
    const uint32_t n = end_start_[v + 1] - end_start_[v];
    vertex_scale_.push_back(n == 0 ? Real(0) : Real(settings.omega / double(n)));
  }
}

template <class Real>
void SpringSolver<Real>::gaussSeidelSerial(SolverState<Real>& state) const {
  if (settings_.colour_major) {
    for (uint32_t s : system_.colour_order) project(state, s);
  } else {
    for (uint32_t s = 0; s < a_.size(); ++s) project(state, s);
  }
}

template <class Real>
void SpringSolver<Real>::gaussSeidelColoured(SolverState<Real>& state) const {
  // The springs of one colour share no vertex, so their projections commute: the result
  // is bitwise the colour-major serial sweep, whatever TBB's partition.
  for (uint32_t c = 0; c < system_.colour_count; ++c) {
    const uint32_t begin = system_.colour_start[c], end = system_.colour_start[c + 1];
    tbb::parallel_for(tbb::blocked_range<uint32_t>(begin, end, 256),
                      [&](const tbb::blocked_range<uint32_t>& range) {
                        for (uint32_t i = range.begin(); i < range.end(); ++i) {
                          project(state, system_.colour_order[i]);
                        }
                      });
  }
}

template <class Real>
void SpringSolver<Real>::jacobi(SolverState<Real>& state) const {
  const size_t n = state.x.size();
  state.scratch.resize(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 512),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t v = range.begin(); v < range.end(); ++v) {
                        state.scratch[v] = gather(state, state.x, v);
                      }
                    });
  if (settings_.kind == SolverKind::kJacobiChebyshev) {
    const double w =
        chebyshevWeight(state.iteration, state.chebyshev_weight, settings_.rho, settings_.delay);
    state.chebyshev_weight = w;
    if (state.previous.size() != n) state.previous = state.x;
    const Real wr = Real(w);
    // x_{k+1} = x_{k-1} + w (y - x_{k-1}); x_k becomes the previous.
    for (size_t v = 0; v < n; ++v) {
      const mesh::Vec3T<Real>& p = state.previous[v];
      const mesh::Vec3T<Real>& y = state.scratch[v];
      const mesh::Vec3T<Real> next{p.x + wr * (y.x - p.x), p.y + wr * (y.y - p.y),
                                   p.z + wr * (y.z - p.z)};
      state.previous[v] = state.x[v];
      state.x[v] = next;
    }
  } else {
    state.x.swap(state.scratch);
  }
}

template <class Real>
void SpringSolver<Real>::iterate(SolverState<Real>& state, size_t count) const {
  assert(state.x.size() == system_.vertex_count && state.anchors.size() >= system_.anchor_count);
  for (size_t i = 0; i < count; ++i) {
    switch (settings_.kind) {
      case SolverKind::kGaussSeidelSerial:
        gaussSeidelSerial(state);
        break;
      case SolverKind::kGaussSeidelColoured:
        gaussSeidelColoured(state);
        break;
      case SolverKind::kJacobi:
      case SolverKind::kJacobiChebyshev:
        jacobi(state);
        break;
    }
    ++state.iteration;
  }
}

template <class Real>
void SpringSolver<Real>::iterateDispatches(SolverState<Real>& state, size_t dispatches) const {
  const size_t colours = system_.colour_count;
  if (settings_.kind == SolverKind::kJacobi || settings_.kind == SolverKind::kJacobiChebyshev ||
      colours == 0) {
    iterate(state, dispatches);
    return;
  }
  if (settings_.kind == SolverKind::kGaussSeidelSerial && !settings_.colour_major) {
    // No GPU path: the reference runs whole sweeps, as many as the budget buys its coloured
    // twin (rounded, at least one).
    iterate(state, std::max<size_t>(1, (dispatches + colours / 2) / colours));
    return;
  }
  for (size_t d = 0; d < dispatches; ++d) {
    const size_t c = state.sweep_cursor;
    for (uint32_t i = system_.colour_start[c]; i < system_.colour_start[c + 1]; ++i) {
      project(state, system_.colour_order[i]);
    }
    if (++state.sweep_cursor == colours) state.sweep_cursor = 0, ++state.iteration;
  }
}

StretchFigures measureStretch(const SpringSystem& system, const std::vector<mesh::Vec3d>& x,
                              const std::vector<mesh::Vec3d>& anchors, bool surface_only) {
  StretchFigures figures;
  double sum = 0;
  for (const Spring& spring : system.springs) {
    if (surface_only && spring.kind != SpringKind::kSurface) continue;
    const mesh::Vec3d& other = spring.anchored() ? anchors[spring.anchor()] : x[spring.b];
    const double length = tb::mesh::length(other - x[spring.a]);
    const double e = spring.rest_m > 0 ? (length - spring.rest_m) / spring.rest_m
                                       : length / system.length_scale_m;
    sum += e * e;
    figures.max_abs = std::max(figures.max_abs, std::abs(e));
    ++figures.springs;
  }
  figures.rms = figures.springs ? std::sqrt(sum / double(figures.springs)) : 0;
  return figures;
}

template class SpringSolver<float>;
template class SpringSolver<double>;

}  // namespace tb::mass_spring
