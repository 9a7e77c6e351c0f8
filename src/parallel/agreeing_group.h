// flowsurf — errors inside a parallel frame without a hang [docs/parallel.md]. A frame makes
// many collective steps (screen_tiles.h, the dye's halo, IBFVS's outlines); a process that
// throws between two of them (an allocation that fails mid-frame, a driver error) would
// leave the others waiting in the next one. AgreeingGroup wraps a ProcessGroup: before
// every collective step each process states whether it has failed (one integer minimum
// over the group; a second step, the failing text, only when one has). A process that
// threw calls fail() from its handler, which joins the step the others wait in; then every
// process throws the same PeerFailure naming the lowest failing process. A section (one
// or more frames: collectiveSection) ends with such a step, so a process that fails after
// the section's last collective step is met there.
// Cost: one 4-byte minimum per collective step.
#pragma once

#include "core/errors.h"
#include "parallel/process_group.h"

#include <string>

namespace flowsurf::methods {

// The error of one process, as every process of the group reports it: its text and
// "(on process r of n)".
class PeerFailure : public Error {
public:
    using Error::Error;
};

class AgreeingGroup final : public ProcessGroup {
public:
    explicit AgreeingGroup(ProcessGroup& inner) : inner_(inner) {}
    int rank() const override { return inner_.rank(); }
    int size() const override { return inner_.size(); }
    void minInPlace(std::span<float> values) override;
    void minInPlace(std::span<int32_t> values) override;
    void sumInPlace(std::span<float> values) override;
    std::vector<float> gather(std::span<const float> values) override;
    std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) override;

    // Collective: the end of a section; throws PeerFailure if a process has failed.
    void finish() { check({}); }
    // From a handler of this process's own error inside a section: joins the step the
    // others are in and throws the agreed PeerFailure.
    [[noreturn]] void fail(const std::string& error);

private:
    void check(const std::string& error);
    ProcessGroup& inner_;
};

// Runs `section` (collective steps over `group` only) so that an error on any process
// becomes the same PeerFailure on all of them, none left waiting. No group: runs it.
template <class Section>
void collectiveSection(AgreeingGroup* group, Section&& section) {
    if (!group) return section();
    try {
        section();
    } catch (const PeerFailure&) {
        throw;
    } catch (const std::exception& e) {
        group->fail(e.what());
    }
    group->finish();
}

}  // namespace flowsurf::methods
