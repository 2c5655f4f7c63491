// render_wire.hpp — the messages between fractalis and its render worker (render_worker.hpp).
//
// They travel as scene_wire frames (a kind, a length, the payload) over a socket; the frame's
// pixels do not: the worker reads them back from the device straight into a shared memory object
// that fractalis created (frame_passes_at below gives both ends the same layout). fractalis
// trusts nothing the worker sends: every reply is read with WireReader's caps, and the shared
// memory cannot shrink under fractalis (platform/shared_memory.hpp).
#pragma once

#include "plugin/scene_wire.hpp"
#include "render/render_settings.hpp"
#include "render/renderer.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

namespace fr {

// Bumped whenever a message's layout changes; fractalis passes it to the worker, which refuses to
// talk to another version.
constexpr uint32_t kRenderWireVersion = 6;

// Whether a precision sent back by the worker is one a frame ran in (never Auto).
constexpr bool resolved_precision(uint32_t p) {
  return p == static_cast<uint32_t>(Precision::Float) ||
         p == static_cast<uint32_t>(Precision::Double) ||
         p == static_cast<uint32_t>(Precision::DoubleDouble);
}

// Kinds share the frame header with the scene host's (scene_wire.hpp), numbered apart from them.
enum class RenderWireKind : uint32_t {
  Ready = 101,          // worker -> fractalis, first: Reply's head (the device opened, or why not)
  SetScene = 102,       // u64 key, u64 key to forget (0: none), SceneInfo: the scene later
                        // messages name by key
  Prepare = 103,        // u64 key, SceneState, RenderSettings; reply: u32 Precision
  RenderSample = 104,   // u64 key, SceneState, RenderSettings, i32 sample, u32 Readback,
                        // i32 first row, i32 rows (RowBand)
  Finish = 105,         // RenderSettings, u32 Readback, u64 bytes of the shared frame
                        // reply: i32 lanes, u32 Precision (the pixels are in the shared frame)
  EvalCounts = 106,     // reply: EvalCounts
  Probe = 107,          // u64 key, u32 count, count fr_value, u32 count, count x 3 floats,
                        // i32 lanes, u32 Precision, 7 f64 (PairOrigin: the eye's pairs,
                        // the resolution); reply: u32 count, count floats
  Build = 108,          // str source, str options, str description
  Quit = 109,           // exit now
  Reply = 110,          // worker -> fractalis: u32 ReplyStatus, str error, then the call's result
  Building = 111,       // worker -> fractalis, during a call: u32 1 and str description when a
                        // kernel build starts, u32 0 when it has ended
  RenderFrame = 112,    // RenderSample's payload, then u32 Readback, u64 bytes of the shared
                        // frame: a sample and Finish in one round trip; reply: Finish's
  ProbeMaterial = 113,  // u64 key, u32 count, count fr_value, u32 count, count x 3 floats,
                        // fr_frame_constants; reply: u32 count, count floats
  DenoiseRows = 114,    // RenderSettings, i32 pass, i32 first row, i32 rows: a denoiser pass
                        // over a band (Renderer::denoise_rows), answered once queued
};

enum class ReplyStatus : uint32_t {
  Ok = 0,
  BuildFailed = 1,  // the kernel did not compile: the error is the compiler's log
  Failed = 2,       // any other error the worker caught (the device's, a bad request)
};

// Scenes a worker holds at once; fractalis says which one it forgets to make room (the explorer's
// reloads add scenes), so both ends always agree on what it holds.
constexpr size_t kWorkerSceneCount = 32;

// Error text and a scene's source are capped on the way back.
constexpr size_t kMaxWorkerErrorBytes = 64 << 10;

static_assert(std::is_trivially_copyable_v<RenderSettings>,
              "RenderSettings travels as its bytes (both ends are the same build)");
void write_render_settings(WireWriter& w, const RenderSettings& s);
RenderSettings read_render_settings(WireReader& r);

// Where each pass of a width x height frame lies in the shared frame that starts at `base`
// (null: only the size), for what `what` reads back; *total_bytes is the size needed.
FramePassPointers frame_passes_at(uint8_t* base, size_t pixels, Readback what, size_t* total_bytes);

}  // namespace fr
