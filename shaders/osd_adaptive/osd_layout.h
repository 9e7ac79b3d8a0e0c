// osd_adaptive's buffer bindings, named for its shaders and its technique's C++ alike
// (gpu::setStorageBuffer(program, TB_..._BINDING_..., words)).
#ifndef TB_OSD_LAYOUT_H
#define TB_OSD_LAYOUT_H

#define TB_OSD_BINDING_POINTS 1
#define TB_OSD_BINDING_FACE_RANGES 2
#define TB_OSD_BINDING_SUB_PATCHES 3
#define TB_OSD_BINDING_POINT_INDICES 4

#endif
