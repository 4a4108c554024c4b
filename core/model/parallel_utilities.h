// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <exception>

#include "core/model/model_part.h"

namespace mc {

/// Entity count from which loops over elements or conditions run in parallel.
inline constexpr long kMinParallelEntities = 256;
/// Size from which cheap loops over DoFs or vector entries run in parallel.
inline constexpr long kMinParallelDofs = 8192;

/// Runs f(i) for i in [0, n) with OpenMP. An exception thrown in any thread stops nothing else
/// but is rethrown (the first one) after the loop, since exceptions may not cross an OpenMP
/// region.
template <class F>
void ParallelForEachIndex(std::size_t count, F&& f) {
  const long n = static_cast<long>(count);
  std::exception_ptr error;
  // Below a few hundred entities a thread team costs more than it saves (and, on a busy machine,
  // waiting for a descheduled thread dominates small problems), so those loops stay serial.
#pragma omp parallel for schedule(guided, 16) if (n >= kMinParallelEntities)
  for (long i = 0; i < n; ++i) {
    try {
      f(static_cast<std::size_t>(i));
    } catch (...) {
#pragma omp critical(mc_parallel_error)
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

/// Runs f(item) for every item of a node/element/condition container (ParallelForEachIndex).
template <class Container, class F>
void ParallelForEachEntity(const Container& items, F&& f) {
  const std::size_t n = items.size();  // sorts the container before the threads start
  auto first = items.begin();
  ParallelForEachIndex(n, [&](std::size_t i) { f(*first[static_cast<long>(i)]); });
}

/// f(entity) for every active element, then every active condition.
template <class F>
void ForEachActiveEntity(ModelPart& model_part, F&& f) {
  ParallelForEachEntity(model_part.Elements(), [&](Entity& e) {
    if (e.IsActive()) f(e);
  });
  ParallelForEachEntity(model_part.Conditions(), [&](Entity& e) {
    if (e.IsActive()) f(e);
  });
}

}  // namespace mc
