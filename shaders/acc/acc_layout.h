// ACC's buffer bindings, named for acc_surface.glsl and techniques/acc/acc.cpp alike.
#ifndef TB_ACC_LAYOUT_H
#define TB_ACC_LAYOUT_H

#define TB_ACC_BINDING_POSITIONS 1
#define TB_ACC_BINDING_RING_HEADERS 2
#define TB_ACC_BINDING_RING_SLOTS 3
#define TB_ACC_BINDING_PATCHES 4
#define TB_ACC_BINDING_STENCILS 5

#endif
