#include "harness/measures/complete_declarations.h"

#include "harness/measures/measure.h"

namespace tb::measures {

void completeDeclarations(results::Results* results) {
  for (results::MeasureDeclaration& declaration : results->measures) {
    if (!declaration.decision_inputs.empty()) continue;
    if (const Measure* measure = MeasureRegistry::instance().find(declaration.measure)) {
      declaration.decision_inputs = measure->info().decision_inputs;
    }
  }
}

}  // namespace tb::measures
