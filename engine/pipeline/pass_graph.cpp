#include "pipeline/pass_graph.hpp"

#include "core/error.hpp"

namespace vct {

const char* inputName(Input input) {
    switch (input) {
        case Input::Geometry: return "geometry";
        case Input::Materials: return "materials";
        case Input::Lights: return "lights";
        case Input::Camera: return "camera";
        case Input::OutputSize: return "output size";
        case Input::VoxelSettings: return "voxel settings";
        case Input::ShadowSettings: return "shadow settings";
        case Input::PhotonSettings: return "photon settings";
        case Input::ConeSettings: return "cone settings";
        case Input::DisplaySettings: return "display settings";
        case Input::ViewSettings: return "view settings";
        case Input::Count: break;
    }
    return "?";
}

void PassGraph::addPass(const std::string& name, std::vector<Input> inputs, std::vector<std::string> reads,
                        std::vector<std::string> writes) {
    for (const std::string& r : reads)
        if (!lastWriter_.count(r)) fail("pass graph: '", name, "' reads '", r, "' before any pass writes it (engine bug)");
    for (const std::string& w : writes) {
        lastWriter_[w] = name;
        resourceVersion_.emplace(w, 0);
    }
    passes_.push_back({name, std::move(inputs), std::move(reads), std::move(writes), false, {}, {}});
}

std::vector<PassRun> PassGraph::plan(const InputVersions& versions,
                                     const std::function<std::string(const std::string&)>& whyNotNeeded) const {
    std::map<std::string, std::uint64_t> resources = resourceVersion_;
    std::vector<PassRun> runs;
    for (const Pass& pass : passes_) {
        PassRun run{pass.name, false, ""};
        const std::string notNeeded = whyNotNeeded(pass.name);
        if (!notNeeded.empty()) {
            run.reason = "not needed: " + notNeeded;
        } else if (!pass.everRan) {
            run.ran = true;
            run.reason = "first run";
        } else {
            for (Input input : pass.inputs)
                if (versions[std::size_t(input)] != pass.seenInputs[std::size_t(input)]) {
                    run.ran = true;
                    run.reason = std::string(inputName(input)) + " changed";
                    break;
                }
            if (!run.ran)
                for (const std::string& r : pass.reads) {
                    const auto seen = pass.seenResources.find(r);
                    if (seen == pass.seenResources.end() || seen->second != resources.at(r)) {
                        run.ran = true;
                        run.reason = "reads " + r + ", rewritten";
                        break;
                    }
                }
            if (!run.ran) run.reason = "nothing it depends on changed";
        }
        if (run.ran)
            for (const std::string& w : pass.writes) ++resources[w];
        runs.push_back(run);
    }
    return runs;
}

void PassGraph::commit(const std::vector<PassRun>& plan, const InputVersions& versions) {
    for (std::size_t i = 0; i < plan.size() && i < passes_.size(); ++i) {
        if (!plan[i].ran) continue;
        Pass& pass = passes_[i];
        for (const std::string& r : pass.reads) pass.seenResources[r] = resourceVersion_.at(r);
        for (const std::string& w : pass.writes) ++resourceVersion_[w];
        pass.seenInputs = versions;
        pass.everRan = true;
    }
}

void PassGraph::reset() {
    for (Pass& pass : passes_) {
        pass.everRan = false;
        pass.seenResources.clear();
    }
}

}  // namespace vct
