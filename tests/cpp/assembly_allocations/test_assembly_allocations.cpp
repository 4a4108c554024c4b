// SPDX-License-Identifier: BSD-3-Clause
// Issue 2 (speed): once the sparsity pattern exists, a Build() of the block builder does no
// heap allocation (beyond the one-off creation of a thread's buffers), with the real structural
// elements (small displacement hexahedra and tetrahedra with LinearElastic3DLaw, total
// Lagrangian ones with HyperElastic3DLaw) and follower-pressure surface conditions. Allocations are
// counted by replacing the global operator new and the C allocation functions of this executable
// (tests/cpp/common/allocation_counter.h), those of the OpenMP runtime apart.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "core/model/model.h"
#include "core/model/model_part.h"
#include "core/model/registry.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/variables/kernel_variables.h"
#include "structural/application/register_structural_mechanics.h"
#include "tests/cpp/common/allocation_counter.h"

namespace mc {
namespace {

/// Counts the heap allocations made while it lives: by the OpenMP runtime, and by everything else.
class AllocationScope {
 public:
  AllocationScope() {
    test::Reset();
    test::StartCounting();
  }
  ~AllocationScope() { test::StopCounting(); }
  long Count() const { return test::Allocations(); }
  long OpenMpCount() const { return test::OpenMpAllocations(); }
};

struct BuildAllocations {
  long own = 0;     ///< by the builder, scheme, elements, conditions, laws, Eigen, libstdc++
  long openmp = 0;  ///< by libgomp
};

struct Case {
  std::string element;
  std::string law;
  bool tetrahedra;
  bool pressure;  ///< follower pressure conditions on the top face
};

/// Unit cube of n^3 cells (hexahedra, or 6 tetrahedra per cell), bottom fixed, a smooth
/// non-zero displacement field so that finite-strain laws see a real deformation.
struct Block {
  Model model;
  ModelPart& part = model.CreateModelPart("Structure");
  Block(const Case& c, int n) {
    RegisterStructuralMechanics();
    for (const VariableData* v :
         {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&REACTION),
          static_cast<const VariableData*>(&POSITIVE_FACE_PRESSURE)})
      part.AddNodalSolutionStepVariable(*v);
    auto id = [n](int i, int j, int k) { return IndexType(1 + i + (n + 1) * (j + (n + 1) * k)); };
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          Node& node = part.CreateNewNode(id(i, j, k), double(i) / n, double(j) / n, double(k) / n);
          node.AddDof(DISPLACEMENT_X, &REACTION_X);
          node.AddDof(DISPLACEMENT_Y, &REACTION_Y);
          node.AddDof(DISPLACEMENT_Z, &REACTION_Z);
          const Array3 x = node.X0();
          node.FastGetSolutionStepValue(DISPLACEMENT) =
              Array3(0.01 * x[0] * x[2], -0.02 * x[1] * x[2] * x[2], -0.03 * x[2] + 0.01 * std::sin(x[0]));
          node.FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE) = k == n ? 2.0 : 0.0;
          if (k == 0) {
            node.Fix(DISPLACEMENT_X);
            node.Fix(DISPLACEMENT_Y);
            node.Fix(DISPLACEMENT_Z);
          }
        }
    Properties& properties = part.GetOrCreateProperties(1);
    properties.SetValue(YOUNG_MODULUS, 210.0);
    properties.SetValue(POISSON_RATIO, 0.3);
    properties.SetConstitutiveLaw(Registry<ConstitutiveLaw>::Instance().GetShared(c.law));
    IndexType element_id = 0, condition_id = 0;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const IndexType v[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                  id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
          if (!c.tetrahedra) {
            part.CreateNewElement(c.element, ++element_id, {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]},
                                  &properties);
          } else {
            // Six positively oriented tetrahedra around the diagonal v0-v6.
            constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                         {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
            for (const auto& t : kTets)
              part.CreateNewElement(c.element, ++element_id, {v[t[0]], v[t[1]], v[t[2]], v[t[3]]}, &properties);
          }
          if (c.pressure && k == n - 1) {
            const IndexType top[4] = {v[4], v[5], v[6], v[7]};
            if (!c.tetrahedra) {
              part.CreateNewCondition("SurfaceLoadCondition3D4N", ++condition_id, {top[0], top[1], top[2], top[3]},
                                      &properties);
            } else {
              part.CreateNewCondition("SurfaceLoadCondition3D3N", ++condition_id, {top[0], top[1], top[2]},
                                      &properties);
              part.CreateNewCondition("SurfaceLoadCondition3D3N", ++condition_id, {top[0], top[2], top[3]},
                                      &properties);
            }
          }
        }
  }
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.element << " + " << c.law << (c.pressure ? " + pressure" : "");
}

class AssemblyAllocations : public ::testing::TestWithParam<Case> {};

TEST(AllocationCounter, CountsOperatorNewAndMalloc) {
  AllocationScope scope;
  std::vector<double> v(10);
  EXPECT_EQ(scope.Count(), 1);
  Matrix m(30, 30);  // Eigen allocates with malloc
  EXPECT_EQ(scope.Count(), 2);
  EXPECT_EQ(scope.OpenMpCount(), 0);
  EXPECT_TRUE(test::OpenMpRuntimeFound());  // the runtime's code was found
}

/// Allocations of each of `repetitions` builds after a first one, with `threads` OpenMP threads.
std::vector<BuildAllocations> CountBuildAllocations(const Case& c, int threads, int repetitions) {
  const int saved_threads = omp_get_max_threads();
  omp_set_num_threads(threads);
  Block block(c, 4);
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  BlockBuilderAndSolver builder(nullptr);
  scheme.Initialize(block.part);
  builder.SetUpDofSet(block.part, scheme);
  builder.SetUpSystem();
  EXPECT_EQ(builder.NumberOfDofs(), 3u * 125u);
  builder.Build(scheme, block.part);  // builds the pattern and sizes every buffer
  const SparseMatrix first_matrix = builder.SystemMatrix();
  const Vector first_rhs = builder.SystemRhs();
  EXPECT_GT(first_rhs.norm(), 0.0);

  std::vector<BuildAllocations> counts;
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    AllocationScope scope;
    builder.Build(scheme, block.part);
    counts.push_back({scope.Count(), scope.OpenMpCount()});
  }
  omp_set_num_threads(saved_threads);
  EXPECT_EQ(builder.PatternBuildCount(), 1);
  // The same system every time (up to the summation order of the threads).
  const double scale = first_matrix.coeffs().cwiseAbs().maxCoeff();
  const SparseMatrix difference = builder.SystemMatrix() - first_matrix;
  EXPECT_LT(difference.coeffs().cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_LT((builder.SystemRhs() - first_rhs).cwiseAbs().maxCoeff(), 1e-13 * first_rhs.cwiseAbs().maxCoeff());
  return counts;
}

// One thread: every buffer was sized by the first build, so later builds allocate nothing; only
// libgomp allocates one team per parallel region (4 per build: elements, conditions, and two in
// the Dirichlet conditions).
TEST_P(AssemblyAllocations, LaterBuildsAllocateNothingOnOneThread) {
  for (const BuildAllocations& count : CountBuildAllocations(GetParam(), 1, 3)) {
    EXPECT_EQ(count.own, 0);
    EXPECT_LE(count.openmp, 4);
  }
}

// Several threads: the guided schedule may hand a thread its first element or condition only in
// a later build, when its thread_local buffers (and their exit handlers) are created once. That
// warm-up is bounded per thread; any allocation per element or integration point (hundreds
// here) exceeds it.
TEST_P(AssemblyAllocations, LaterBuildsOnlyWarmUpThreadBuffers) {
  const int threads = std::max(2, omp_get_max_threads());
  long total = 0;
  for (const BuildAllocations& count : CountBuildAllocations(GetParam(), threads, 3)) total += count.own;
  EXPECT_LE(total, 32L * threads);
}

INSTANTIATE_TEST_SUITE_P(StructuralElements, AssemblyAllocations,
                         ::testing::Values(Case{"SmallDisplacementElement3D8N", "LinearElastic3DLaw", false, false},
                                           Case{"SmallDisplacementElement3D4N", "LinearElastic3DLaw", true, false},
                                           Case{"TotalLagrangianElement3D8N", "HyperElastic3DLaw", false, false},
                                           Case{"TotalLagrangianElement3D4N", "HyperElastic3DLaw", true, false},
                                           Case{"SmallDisplacementElement3D8N", "LinearElastic3DLaw", false, true},
                                           Case{"SmallDisplacementElement3D4N", "LinearElastic3DLaw", true, true}),
                         [](const auto& info) {
                           const Case& c = info.param;
                           return c.element.substr(0, c.element.find("Element")) + (c.tetrahedra ? "Tet" : "Hex") +
                                  (c.pressure ? "WithPressure" : "");
                         });

}  // namespace
}  // namespace mc
