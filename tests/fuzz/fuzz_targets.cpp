// SPDX-License-Identifier: BSD-3-Clause
#include "fuzz_targets.h"

#include <cstdlib>
#include <iostream>
#include <string>

#include "core/io/mdpa_reader.h"
#include "core/model/model.h"
#include "core/parameters/parameters.h"
#include "core/utilities/error.h"
#include "core/utilities/function_expression.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "structural/application/register_structural_mechanics.h"

namespace mc::fuzz {
namespace {

/// Warnings about skipped blocks are expected on fuzzed input; printing them would dominate the
/// time of each run.
void Silence() {
  static const bool silenced = [] {
    Logger::SetSink([](Logger::Level, const std::string&) {});
    return true;
  }();
  (void)silenced;
}

/// An invariant the code under test broke: reported like a crash, so libFuzzer keeps the input.
[[noreturn]] void Broken(const std::string& what) {
  std::cerr << "fuzz invariant broken: " << what << "\n";
  std::abort();
}

/// `probe`: also call the getters of the wrong type (costly: each throws); done for the first
/// items of an array only, so long arrays of numbers do not dominate the run time.
void ReadEverything(const Parameters& value, bool probe) {
  (void)value.Where();
  if (value.IsSubParameter()) {
    for (const std::string& key : value.Keys()) {
      if (!value.Has(key)) Broken("Keys() lists '" + key + "' but Has() denies it");
      ReadEverything(value[key], probe);
    }
  } else if (value.IsArray()) {
    for (std::size_t i = 0; i < value.size(); ++i) ReadEverything(value[i], probe && i < 4);
    if (value.IsVector()) (void)value.GetVector();
    if (value.IsMatrix()) (void)value.GetMatrix();
    if (value.IsStringArray()) (void)value.GetStringArray();
  } else if (value.IsDouble()) {
    (void)value.GetDouble();
  } else if (value.IsBool()) {
    (void)value.GetBool();
  } else if (value.IsString()) {
    (void)value.GetString();
  }
  if (!probe) return;
  // Wrong-type getters must answer with an InputError naming the path.
  for (auto getter :
       {+[](const Parameters& p) { (void)p.GetDouble(); }, +[](const Parameters& p) { (void)p.GetInt(); },
        +[](const Parameters& p) { (void)p.GetBool(); }, +[](const Parameters& p) { (void)p.GetString(); },
        +[](const Parameters& p) { (void)p.GetVector(); }, +[](const Parameters& p) { (void)p.GetMatrix(); },
        +[](const Parameters& p) { (void)p.GetStringArray(); },
        +[](const Parameters& p) { (void)p["solver_settings"]; },
        +[](const Parameters& p) { (void)p[std::size_t{3}]; }}) {
    try {
      getter(value);
    } catch (const InputError&) {
    }
  }
}

const char* const kDefaults = R"({
  "problem_data": {"problem_name": "", "echo_level": 0, "start_time": 0.0, "end_time": 1.0},
  "solver_settings": {"solver_type": "Static", "max_iteration": 10, "line_search": false,
                      "linear_solver_settings": {}, "tolerances": [1e-4, 1e-9], "matrix": [[1, 0], [0, 1]]},
  "processes": {"constraints_process_list": [], "loads_process_list": []},
  "output_processes": {}
})";

void Validate(const Parameters& settings, const Parameters& defaults) {
  // Defaults come from code, always an object: another kind is a programming error (mc::Error).
  if (!defaults.IsSubParameter()) return;
  using Method = void (Parameters::*)(const Parameters&);
  for (const Method method : {&Parameters::ValidateAndAssignDefaults, &Parameters::RecursivelyValidateAndAssignDefaults,
                              &Parameters::AddMissingParameters, &Parameters::RecursivelyAddMissingParameters}) {
    Parameters copy = settings.Clone();
    try {
      (copy.*method)(defaults);
    } catch (const InputError&) {
    }
  }
}

}  // namespace

void ReadMdpa(std::string_view text) {
  Silence();
  static const bool registered = [] {
    RegisterStructuralMechanics();
    return true;
  }();
  (void)registered;
  Model model;
  ModelPart& part = model.CreateModelPart("Structure");
  for (const VariableData* var :
       {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&REACTION),
        static_cast<const VariableData*>(&VELOCITY), static_cast<const VariableData*>(&TEMPERATURE)})
    part.AddNodalSolutionStepVariable(*var);
  for (const bool tolerant : {false, true}) {
    MdpaReader reader("fuzz.mdpa", MdpaReaderOptions{tolerant});
    Model fresh;
    ModelPart& target = tolerant ? fresh.CreateModelPart("Structure") : part;
    try {
      reader.ReadModelPartFromText(text, target);
      MdpaReader::ApplyFixityRequests(reader.FixityRequests());
    } catch (const InputError&) {
    }
  }
}

void ReadParameters(std::string_view text) {
  const std::size_t split = text.find('\0');
  const std::string settings_text(text.substr(0, split));
  Parameters settings;
  try {
    settings = Parameters(settings_text, "fuzz.json");
  } catch (const InputError&) {
    return;
  }
  ReadEverything(settings, true);
  const std::string written = settings.WriteJsonString();
  if (Parameters(written).WriteJsonString() != written) Broken("writing and reading back changed the document");
  (void)settings.PrettyPrintJsonString();
  Validate(settings, settings);
  Validate(settings, Parameters(kDefaults));
  if (split != std::string_view::npos) {
    try {
      const Parameters defaults(std::string(text.substr(split + 1)), "defaults.json");
      Validate(settings, defaults);
      Validate(defaults, settings);
    } catch (const InputError&) {
    }
  }
}

void ParseExpression(std::string_view text) {
  try {
    const FunctionExpression expression{std::string(text)};
    for (const double t : {0.0, 1.0, -2.5}) (void)expression.Evaluate(0.5 * t, -t, 2.0, t, 1.0, 0.0, -1.0);
    (void)expression.DependsOnSpace();
    (void)expression.DependsOnTime();
  } catch (const InputError&) {
  }
}

}  // namespace mc::fuzz
