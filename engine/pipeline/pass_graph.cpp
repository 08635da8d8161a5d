#include "pipeline/pass_graph.hpp"

namespace vct {

std::array<PassGraph::PassState, kPassCount> PassGraph::freshState() {
    std::array<PassState, kPassCount> state{};
    for (PassState& s : state) s.seenResources.fill(kNeverRead);
    return state;
}

namespace {
// The passes whose results `targets` need: walking the table backwards, a pass is needed when it
// writes something needed, and then what it reads is needed too.
std::array<bool, kPassCount> passesFor(ResourceSet targets) {
    std::array<bool, kPassCount> needed{};
    ResourceSet wanted = targets;
    const PassTable& table = framePasses();
    for (std::size_t i = kPassCount; i-- > 0;)
        if (table[i].writes.intersects(wanted)) {
            needed[i] = true;
            wanted |= table[i].reads;
        }
    return needed;
}
}  // namespace

std::vector<PassRun> PassGraph::plan(const InputVersions& versions, const RenderSettings& settings,
                                     ResourceSet targets) const {
    std::array<std::uint64_t, kResourceCount> resources = resourceVersion_;
    const std::array<bool, kPassCount> asked = passesFor(targets);
    std::vector<PassRun> runs;
    for (const PassDeclaration& pass : framePasses()) {
        const PassState& state = state_[std::size_t(pass.pass)];
        PassRun run{pass.pass, pass.name, false, ""};
        const char* notNeeded = pass.whyNotNeeded(settings);
        if (!asked[std::size_t(pass.pass)]) {
            run.reason = "not needed: not asked for";
        } else if (notNeeded) {
            run.reason = std::string("not needed: ") + notNeeded;
        } else if (!state.everRan) {
            run.ran = true;
            run.reason = "first run";
        } else {
            pass.inputs.forEach([&](Input input) {
                if (!run.ran && versions[std::size_t(input)] != state.seenInputs[std::size_t(input)]) {
                    run.ran = true;
                    run.reason = std::string(inputName(input)) + " changed";
                }
            });
            pass.reads.forEach([&](Resource r) {
                if (!run.ran && state.seenResources[std::size_t(r)] != resources[std::size_t(r)]) {
                    run.ran = true;
                    run.reason = std::string("reads ") + resourceName(r) + ", rewritten";
                }
            });
            if (!run.ran) run.reason = "nothing it depends on changed";
        }
        if (run.ran) pass.writes.forEach([&](Resource w) { ++resources[std::size_t(w)]; });
        runs.push_back(run);
    }
    return runs;
}

void PassGraph::commit(const std::vector<PassRun>& plan, const InputVersions& versions) {
    for (const PassRun& run : plan) {
        if (!run.ran) continue;
        const PassDeclaration& pass = declaration(run.pass);
        PassState& state = state_[std::size_t(run.pass)];
        pass.reads.forEach([&](Resource r) { state.seenResources[std::size_t(r)] = resourceVersion_[std::size_t(r)]; });
        pass.writes.forEach([&](Resource w) { ++resourceVersion_[std::size_t(w)]; });
        state.seenInputs = versions;
        state.everRan = true;
    }
}

void PassGraph::reset() { state_ = freshState(); }

}  // namespace vct
