// The spring projection shared by the mass-spring solvers (seed 003; Jakobsen's signs): the
// correction an end at `self` takes towards `other`, in the operation order of
// techniques/mass_spring/spring_solvers.h (springCorrection). `precise` keeps the
// operations unfused and in order, so the GPU repeats the CPU twin's float arithmetic.
const uint kAnchorBit = 0x80000000u;

vec3 springCorrection(vec3 self, vec3 other, float rest, float weight) {
  precise float dx = other.x - self.x;
  precise float dy = other.y - self.y;
  precise float dz = other.z - self.z;
  precise float length = sqrt(dx * dx + dy * dy + dz * dz);
  if (!(length > 0.0)) return vec3(0.0);
  precise float f = weight * ((length - rest) / length);
  precise vec3 c = vec3(dx * f, dy * f, dz * f);
  return c;
}
