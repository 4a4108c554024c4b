// SPDX-License-Identifier: BSD-3-Clause
// Test doubles and helpers for the IO tests (see io_test_utilities.h).
#include "io_test_utilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/model/registry.h"

namespace mc::test {

GeometryType GeometryTypeOfName(const std::string& name, bool is_condition) {
  std::smatch m;
  static const std::regex suffix("([23])D([0-9]+)N$");
  if (!std::regex_search(name, m, suffix)) throw std::runtime_error("no dimension suffix in " + name);
  const int dim = std::stoi(m[1]);
  const int n = std::stoi(m[2]);
  const bool surface = is_condition || name.find("Membrane") != std::string::npos;
  if (dim == 2) {
    switch (n) {
      case 1: return GeometryType::Point2D;
      case 2: return GeometryType::Line2D2;
      case 3: return GeometryType::Triangle2D3;
      case 4: return GeometryType::Quadrilateral2D4;
      case 6: return GeometryType::Triangle2D6;
      case 8: return GeometryType::Quadrilateral2D8;
      case 9: return GeometryType::Quadrilateral2D9;
    }
  } else {
    switch (n) {
      case 1: return GeometryType::Point3D;
      case 2: return GeometryType::Line3D2;
      case 3: return GeometryType::Triangle3D3;
      case 4: return surface ? GeometryType::Quadrilateral3D4 : GeometryType::Tetrahedra3D4;
      case 6: return surface ? GeometryType::Triangle3D6 : GeometryType::Prism3D6;
      case 8: return surface ? GeometryType::Quadrilateral3D8 : GeometryType::Hexahedra3D8;
      case 9: return GeometryType::Quadrilateral3D9;
      case 10: return GeometryType::Tetrahedra3D10;
      case 20: return GeometryType::Hexahedra3D20;
      case 27: return GeometryType::Hexahedra3D27;
    }
  }
  throw std::runtime_error("no geometry for " + name);
}

void RegisterElement(const std::string& name) {
  Registry<Element>::Instance().Add(
      name, std::make_shared<NamedEntity<Element>>(name, 0, Geometry(GeometryTypeOfName(name, false), {}), nullptr));
}

void RegisterCondition(const std::string& name) {
  Registry<Condition>::Instance().Add(
      name, std::make_shared<NamedEntity<Condition>>(name, 0, Geometry(GeometryTypeOfName(name, true), {}), nullptr));
}

void RegisterLaw(const std::string& name) {
  Registry<ConstitutiveLaw>::Instance().Add(name, std::make_shared<NamedLaw>(name));
}

void RegisterEntitiesNamedIn(const std::string& mdpa_text) {
  static const std::regex block("Begin[ \\t]+(Elements|Conditions)[ \\t]+([A-Za-z0-9_]+)");
  for (auto it = std::sregex_iterator(mdpa_text.begin(), mdpa_text.end(), block); it != std::sregex_iterator(); ++it) {
    if ((*it)[1] == "Elements")
      RegisterElement((*it)[2]);
    else
      RegisterCondition((*it)[2]);
  }
}

std::string ReadFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string CasesDir() { return std::string(MC_TEST_CASES_DIR) + "/kratos_csma"; }

std::vector<std::string> CaseFiles(const std::string& suffix) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(CasesDir())) {
    const std::string path = entry.path().string();
    if (entry.is_regular_file() && path.size() > suffix.size() &&
        path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0)
      files.push_back(path);
  }
  std::sort(files.begin(), files.end());
  return files;
}

namespace {

bool SameValue(const DataValueContainer::Value& a, const DataValueContainer::Value& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        const T& y = std::get<T>(b);
        if constexpr (std::is_same_v<T, Array3> || std::is_same_v<T, Vector> || std::is_same_v<T, Matrix>)
          return x.rows() == y.rows() && x.cols() == y.cols() && x == y;
        else
          return x == y;
      },
      a);
}

void ExpectSameData(const DataValueContainer& a, const DataValueContainer& b, const std::string& where) {
  ASSERT_EQ(a.Size(), b.Size()) << where;
  for (const auto& [var, value] : a.Items()) {
    const auto it =
        std::find_if(b.Items().begin(), b.Items().end(), [&](const auto& item) { return item.first == var; });
    ASSERT_NE(it, b.Items().end()) << where << ": " << var->Name() << " missing";
    EXPECT_TRUE(SameValue(value, it->second)) << where << ": " << var->Name() << " differs";
  }
}

template <class T>
void ExpectSameEntities(const EntityContainer<T>& a, const EntityContainer<T>& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const T& x = *a[i];
    const T& y = *b[i];
    ASSERT_EQ(x.Id(), y.Id()) << where;
    EXPECT_EQ(x.RegisteredName(), y.RegisteredName()) << where << " " << x.Id();
    EXPECT_EQ(x.pGetProperties()->Id(), y.pGetProperties()->Id()) << where << " " << x.Id();
    ASSERT_EQ(x.GetGeometry().PointsNumber(), y.GetGeometry().PointsNumber());
    for (std::size_t k = 0; k < x.GetGeometry().PointsNumber(); ++k)
      EXPECT_EQ(x.GetGeometry()[k].Id(), y.GetGeometry()[k].Id()) << where << " " << x.Id();
    ExpectSameData(x.Data(), y.Data(), where + " data of " + std::to_string(x.Id()));
  }
}

template <class T>
std::vector<IndexType> Ids(const EntityContainer<T>& items) {
  std::vector<IndexType> ids;
  for (const T* item : items) ids.push_back(item->Id());
  return ids;
}

std::vector<IndexType> PropertyIds(const ModelPart& part) {
  std::vector<IndexType> ids;
  for (const Properties* p : part.PropertiesList()) ids.push_back(p->Id());
  return ids;
}

void ExpectSameTree(const ModelPart& a, const ModelPart& b) {
  const std::string where = a.FullName();
  EXPECT_EQ(a.Name(), b.Name());
  EXPECT_EQ(Ids(a.Nodes()), Ids(b.Nodes())) << where;
  EXPECT_EQ(Ids(a.Elements()), Ids(b.Elements())) << where;
  EXPECT_EQ(Ids(a.Conditions()), Ids(b.Conditions())) << where;
  EXPECT_EQ(PropertyIds(a), PropertyIds(b)) << where;
  ASSERT_EQ(a.Tables().size(), b.Tables().size()) << where;
  for (const auto& [id, table] : a.Tables()) {
    ASSERT_TRUE(b.HasTable(id)) << where;
    EXPECT_EQ(table.Data(), b.GetTable(id).Data()) << where;
    EXPECT_EQ(table.InputVariable(), b.GetTable(id).InputVariable()) << where;
  }
  ASSERT_EQ(a.SubModelPartNames(), b.SubModelPartNames()) << where;
  for (const ModelPart* sub : a.SubModelParts()) ExpectSameTree(*sub, b.GetSubModelPart(sub->Name()));
}

}  // namespace

void ExpectSameModelPart(const ModelPart& a, const ModelPart& b) {
  ASSERT_EQ(a.NumberOfNodes(), b.NumberOfNodes());
  const VariablesList& variables = a.GetNodalSolutionStepVariablesList();
  for (std::size_t i = 0; i < a.NumberOfNodes(); ++i) {
    const Node& x = *a.Nodes()[i];
    const Node& y = *b.Nodes()[i];
    ASSERT_EQ(x.Id(), y.Id());
    EXPECT_EQ(x.X0(), y.X0()) << "node " << x.Id();
    for (std::size_t k = 0; k < variables.Stride(); ++k)
      EXPECT_EQ(const_cast<Node&>(x).StepData()[k], const_cast<Node&>(y).StepData()[k]) << "node " << x.Id();
    ExpectSameData(x.Data(), y.Data(), "node " + std::to_string(x.Id()));
  }
  ExpectSameEntities(a.Elements(), b.Elements(), "elements");
  ExpectSameEntities(a.Conditions(), b.Conditions(), "conditions");
  ExpectSameData(a.GetProcessInfo(), b.GetProcessInfo(), "process info");
  for (const Properties* p : a.PropertiesList()) {
    const Properties& q = b.GetProperties(p->Id());
    ExpectSameData(*p, q, "properties " + std::to_string(p->Id()));
    ASSERT_EQ(p->Tables().size(), q.Tables().size());
    for (const auto& [key, table] : p->Tables()) EXPECT_EQ(table.Data(), q.GetTable(key.first, key.second).Data());
  }
  ExpectSameTree(a, b);
}

}  // namespace mc::test
