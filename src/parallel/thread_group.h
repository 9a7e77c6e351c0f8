// flowsurf — N threads of one program as a ProcessGroup: what MPI is to the ParaView plugin's
// ranks (process_group.h), in memory. Each collective writes this member's contribution to
// its slot, waits for all members, reads the result, and waits again before the slots are
// reused. Used by `flowsurf bench --ranks` (each thread with its own GL context and piece)
// and by the parallel tests. Cost: two barrier waits and one copy of the data per call.
#pragma once

#include "parallel/process_group.h"

#include <barrier>
#include <cstdint>
#include <span>
#include <vector>

namespace flowsurf::methods {

class ThreadGroup {
public:
    explicit ThreadGroup(int n);

    // Rank `rank` of the group; one per thread, each used by its thread only.
    class Member final : public ProcessGroup {
    public:
        Member(ThreadGroup& g, int rank) : g_(g), rank_(rank) {}
        int rank() const override { return rank_; }
        int size() const override { return g_.n_; }
        void minInPlace(std::span<float> v) override;
        void minInPlace(std::span<int32_t> v) override;
        void sumInPlace(std::span<float> v) override;
        std::vector<float> gather(std::span<const float> v) override;
        std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) override;

    private:
        template <class T, class Op>
        void reduce(std::vector<std::vector<T>>& slots, std::span<T> v, Op op);
        ThreadGroup& g_;
        int rank_;
    };

private:
    int n_;
    std::barrier<> sync_;
    std::vector<std::vector<float>> floats_;
    std::vector<std::vector<int32_t>> ints_;
    std::vector<std::vector<std::vector<uint8_t>>> messages_;  // [sender][receiver]
};

}  // namespace flowsurf::methods
