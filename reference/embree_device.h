// Internal: the process-wide Embree device, and turning Embree's per-thread error
// code into an exception.
#pragma once

#include <embree3/rtcore.h>

#include <string>

namespace tb::ref {

// Created on first use and kept for the life of the process (a device owns Embree's
// thread pool, so one per object would be wasteful). Thread-safe.
RTCDevice sharedEmbreeDevice();

// Throws InputError(source, element, "Embree failed: ...") when the calling thread's
// last Embree call on the shared device failed.
void throwOnEmbreeError(const std::string& source, const std::string& element);

}  // namespace tb::ref
