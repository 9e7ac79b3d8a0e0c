// gregory_acc's buffer bindings, named for its shaders and its technique's C++ alike
// (gpu::setStorageBuffer(program, TB_..._BINDING_..., words)).
#ifndef TB_GREGORY_LAYOUT_H
#define TB_GREGORY_LAYOUT_H

#define TB_GREGORY_BINDING_VERTICES 1
#define TB_GREGORY_BINDING_STENCIL_OFFSETS 2
#define TB_GREGORY_BINDING_STENCIL_ENTRIES 3
#define TB_GREGORY_BINDING_PATCH_POINTS 4

#endif
