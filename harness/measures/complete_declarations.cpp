#include "harness/measures/complete_declarations.h"

#include "harness/measures/measure.h"

namespace tb::measures {

void completeDeclarations(results::Results* results) {
  for (results::MeasureDeclaration& declaration : results->measures) {
    const Measure* measure = MeasureRegistry::instance().find(declaration.measure);
    if (measure == nullptr) continue;
    if (declaration.decision_inputs.empty()) {
      declaration.decision_inputs = measure->info().decision_inputs;
    }
    if (declaration.shader_db.group_key.empty()) declaration.shader_db = measure->info().shader_db;
  }
}

}  // namespace tb::measures
