// The render worker's side of render_worker.hpp: one device, one renderer, requests one at a
// time. Errors the worker can catch (a kernel that does not compile, a device error, a request it
// cannot read) are replies; what it cannot catch (a DE's crash, a hang) fractalis sees as the
// process ending or not answering.
#include "platform/shared_memory.hpp"
#include "plugin/wire_io.hpp"
#include "render/de_probe.hpp"
#include "render/kernel_assembly.hpp"
#include "worker/render_wire.hpp"
#include "worker/render_worker.hpp"

#include <map>

namespace fr {
namespace {

WireKind wire(RenderWireKind k) {
  return static_cast<WireKind>(k);
}

bool send_reply(Channel& channel, RenderWireKind kind, ReplyStatus status, const std::string& error,
                const std::string& result) {
  WireWriter w;
  w.u32(static_cast<uint32_t>(status));
  w.str(error.size() > kMaxWorkerErrorBytes ? error.substr(0, kMaxWorkerErrorBytes) : error);
  w.raw(result.data(), result.size());
  return write_frame(channel, wire(kind), w.bytes());
}

struct BadRequest : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Worker {
 public:
  Worker(Channel& channel, NativeHandle frame_handle, const DeviceInfo& device)
      : channel_(channel), frame_(frame_handle), runtime_(device), renderer_(runtime_) {
    runtime_.on_build = [this](const std::string* description) {
      WireWriter w;
      w.u32(description ? 1 : 0);
      w.str(description ? *description : "");
      write_frame(channel_, wire(RenderWireKind::Building), w.bytes());
    };
  }

  // What both probes start with (render_worker.cpp's write_probe_request): the scene, its
  // parameter values and the points.
  struct ProbeRequest {
    const SceneInfo* info = nullptr;
    std::vector<fr_value> params;
    std::vector<std::array<float, 3>> points;
  };
  ProbeRequest read_probe_request(WireReader& r) {
    ProbeRequest q;
    q.info = &scene(r.u64());
    const uint32_t param_count = r.u32();
    if (param_count != q.info->params.size()) throw BadRequest("wrong parameter count");
    q.params.resize(param_count);
    r.raw(q.params.data(), q.params.size() * sizeof(fr_value));
    const uint32_t point_count = r.u32();
    if (point_count > r.rest().size() / sizeof(std::array<float, 3>))
      throw BadRequest("too many points");
    q.points.resize(point_count);
    r.raw(q.points.data(), q.points.size() * sizeof(q.points[0]));
    return q;
  }

  // Answers one request into *result; throws for an error to send back.
  void answer(RenderWireKind kind, WireReader& r, WireWriter& result) {
    switch (kind) {
      case RenderWireKind::SetScene: {
        const uint64_t key = r.u64();
        const uint64_t forget = r.u64();
        SceneInfo info;
        if (!read_scene_info(r, &info)) throw BadRequest("a malformed scene");
        if (forget != 0) scenes_.erase(forget);
        if (scenes_.size() >= kWorkerSceneCount) throw BadRequest("more scenes than it holds");
        scenes_[key] = std::move(info);
        return;
      }
      case RenderWireKind::Prepare: {
        const SceneInfo& info = scene(r.u64());
        const SceneState state = read_state(r, info);
        const RenderSettings settings = read_render_settings(r);
        check(r);
        result.u32(static_cast<uint32_t>(renderer_.prepare(info, state, settings)));
        return;
      }
      case RenderWireKind::RenderSample: {
        const Sample sample = read_sample(r);
        check(r);
        render(sample);
        // Answered once the sample is queued: it runs while the answer travels. The next
        // sample's upload (a blocking write) or the finish waits for it, so fractalis's limit on
        // those calls is this sample's limit.
        return;
      }
      case RenderWireKind::Finish: {
        const RenderSettings settings = read_render_settings(r);
        const uint32_t what = r.u32();
        const uint64_t bytes = r.u64();
        check(r);
        finish(settings, what, bytes, result);
        return;
      }
      case RenderWireKind::RenderFrame: {
        const Sample sample = read_sample(r);
        const uint32_t what = r.u32();
        const uint64_t bytes = r.u64();
        check(r);
        render(sample);
        finish(sample.settings, what, bytes, result);
        return;
      }
      case RenderWireKind::EvalCounts: {
        const EvalCounts counts = renderer_.eval_counts();
        result.raw(&counts, sizeof counts);
        return;
      }
      case RenderWireKind::Probe: {
        const ProbeRequest q = read_probe_request(r);
        const SceneInfo& info = *q.info;
        const auto& params = q.params;
        const auto& points = q.points;
        const int lanes = r.i32();
        const uint32_t precision = r.u32();
        PairOrigin origin;
        for (DoubleDouble& c : origin.eye) {
          c.hi = r.f64();
          c.lo = r.f64();
        }
        origin.resolution_rad = static_cast<float>(r.f64());
        check(r);
        if (precision > static_cast<uint32_t>(Precision::DoubleDouble))
          throw BadRequest("bad precision");
        const std::vector<float> values = probe_de(runtime_, info, params, points, lanes,
                                                   static_cast<Precision>(precision), &origin);
        result.u32(static_cast<uint32_t>(values.size()));
        result.raw(values.data(), values.size() * sizeof(float));
        return;
      }
      case RenderWireKind::ProbeMaterial: {
        const ProbeRequest q = read_probe_request(r);
        const SceneInfo& info = *q.info;
        const auto& params = q.params;
        const auto& points = q.points;
        fr_frame_constants fc;
        r.raw(&fc, sizeof fc);
        check(r);
        if (!has_material_function(info)) throw BadRequest("the scene has no material function");
        const std::vector<float> values = probe_material(runtime_, info, params, fc, points);
        result.u32(static_cast<uint32_t>(values.size()));
        result.raw(values.data(), values.size() * sizeof(float));
        return;
      }
      case RenderWireKind::DenoiseRows: {
        const RenderSettings settings = read_render_settings(r);
        const int pass = r.i32();
        RowBand rows;
        rows.first_row_px = r.i32();
        rows.rows_px = r.i32();
        check(r);
        renderer_.denoise_rows(settings, pass, rows);
        return;
      }
      case RenderWireKind::Build: {
        const std::string source = r.str(64u << 20);
        const std::string options = r.str(1u << 20);
        const std::string description = r.str(1u << 20);
        check(r);
        runtime_.program(source, options, description);
        return;
      }
      default:
        throw BadRequest("an unknown request " + std::to_string(static_cast<uint32_t>(kind)));
    }
  }

 private:
  struct Sample {
    const SceneInfo* info;
    SceneState state;
    RenderSettings settings;
    int index;
    uint32_t outputs;
    RowBand rows;
  };
  Sample read_sample(WireReader& r) const {
    Sample s;
    s.info = &scene(r.u64());
    s.state = read_state(r, *s.info);
    s.settings = read_render_settings(r);
    s.index = r.i32();
    s.outputs = r.u32();
    s.rows.first_row_px = r.i32();
    s.rows.rows_px = r.i32();
    return s;
  }
  void render(const Sample& s) {
    if (s.outputs > static_cast<uint32_t>(Readback::Everything)) throw BadRequest("bad outputs");
    renderer_.render_sample(*s.info, s.state, s.settings, s.index, static_cast<Readback>(s.outputs),
                            s.rows);
  }
  // Reads the frame's passes `what` into the shared frame, which fractalis made `bytes` long;
  // the reply carries the lanes and precision.
  void finish(const RenderSettings& settings, uint32_t what, uint64_t bytes, WireWriter& result) {
    if (what > static_cast<uint32_t>(Readback::Everything)) throw BadRequest("bad passes");
    const size_t n = static_cast<size_t>(settings.width_px) * settings.height_px;
    size_t need = 0;
    frame_passes_at(nullptr, n, static_cast<Readback>(what), &need);
    std::string error;
    if (need > bytes || !frame_.map_at_least(need, &error))
      throw BadRequest(error.empty() ? "the shared frame is too small" : error);
    // The display image (at the frame's start) is written there by the post stage itself.
    renderer_.set_display_memory(frame_.data(), (n * 4 + 63) / 64 * 64);
    const Renderer::FinishedFrame f = renderer_.finish_into(
        settings, static_cast<Readback>(what),
        frame_passes_at(frame_.data(), n, static_cast<Readback>(what), &need));
    result.i32(f.lanes);
    result.u32(static_cast<uint32_t>(f.precision));
  }
  const SceneInfo& scene(uint64_t key) const {
    const auto it = scenes_.find(key);
    if (it == scenes_.end()) throw BadRequest("a scene it was not sent");
    return it->second;
  }
  static SceneState read_state(WireReader& r, const SceneInfo& info) {
    SceneState state;
    if (!read_scene_state(r, info.params.size(), info.lights.size(), &state))
      throw BadRequest("a malformed scene state");
    return state;
  }
  static void check(const WireReader& r) {
    if (r.failed()) throw BadRequest("a malformed request");
  }

  Channel& channel_;
  SharedMemory frame_;
  ClRuntime runtime_;
  Renderer renderer_;
  std::map<uint64_t, SceneInfo> scenes_;
};

}  // namespace

int run_render_worker(Channel& channel, NativeHandle frame_handle,
                      const std::string& device_selector) {
  std::unique_ptr<Worker> worker;
  try {
    std::string error;
    const std::optional<DeviceInfo> device = select_device(list_devices(), device_selector, &error);
    if (!device) {
      send_reply(channel, RenderWireKind::Ready, ReplyStatus::Failed, error, "");
      return 1;
    }
    worker = std::make_unique<Worker>(channel, frame_handle, *device);
  } catch (const std::exception& e) {
    send_reply(channel, RenderWireKind::Ready, ReplyStatus::Failed, e.what(), "");
    return 1;
  }
  if (!send_reply(channel, RenderWireKind::Ready, ReplyStatus::Ok, "", "")) return 0;
  for (;;) {
    WireKind kind{};
    std::string payload;
    if (read_frame(channel, -1, &kind, &payload) != ReadStatus::Ok) return 0;  // fractalis left
    const auto k = static_cast<RenderWireKind>(kind);
    if (k == RenderWireKind::Quit) return 0;
    WireReader r(payload);
    WireWriter result;
    ReplyStatus status = ReplyStatus::Ok;
    std::string error;
    try {
      worker->answer(k, r, result);
    } catch (const KernelBuildError& e) {
      status = ReplyStatus::BuildFailed;
      error = e.what();
    } catch (const BadRequest& e) {
      status = ReplyStatus::Failed;
      error = std::string("the render worker was sent ") + e.what();
    } catch (const std::exception& e) {
      status = ReplyStatus::Failed;
      error = e.what();
    }
    if (!send_reply(channel, RenderWireKind::Reply, status, error, result.bytes())) return 0;
  }
}

}  // namespace fr
