// Declarations read from an older results.json lack what the measures declare since
// (decision inputs, the shader-db summary): the registered measure of the same id supplies them.
#pragma once

#include "harness/results/results_model.h"

namespace tb::measures {

// Fills each declaration's empty decision_inputs and shader_db from the registered measure
// of its id (MeasureRegistry); a measure this binary does not know keeps what the file says.
void completeDeclarations(results::Results* results);

}  // namespace tb::measures
