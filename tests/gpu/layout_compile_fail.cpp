// Layout.CppOnlyFieldFailsToBuild compiles this with TB_LAYOUT_TEST_CPP_FIELD, which gives
// every shared block a C++-only leading field (shaders/common/layout/tb_layout.h): the
// headers' static_asserts must then fail. Layout.SharedHeadersBuild compiles it plain.
#include "shaders/common/layout/capture_layout.h"
#include "shaders/common/layout/capture_record.h"
#include "shaders/common/layout/cull_layout.h"
#include "shaders/common/layout/factor_layout.h"
#include "shaders/common/layout/levels_layout.h"
#include "shaders/common/layout/tess_patch_record.h"

int main() { return 0; }
