#include "parallel/agreeing_group.h"

#include <climits>
#include <cstdint>

namespace flowsurf::methods {

void AgreeingGroup::check(const std::string& error) {
    int32_t failed = error.empty() ? INT32_MAX : int32_t(rank());
    inner_.minInPlace(std::span<int32_t>(&failed, 1));
    if (failed == INT32_MAX) return;
    const std::vector<std::vector<uint8_t>> texts = allGather(inner_, std::vector<uint8_t>(error.begin(), error.end()));
    std::string text(texts.at(size_t(failed)).begin(), texts.at(size_t(failed)).end());
    text.erase(text.find_last_not_of(" \n\r\t") + 1);
    if (text.empty()) text = "an error without a message";
    throw PeerFailure(text + " (on process " + std::to_string(failed) + " of " + std::to_string(size()) + ")");
}

void AgreeingGroup::fail(const std::string& error) {
    check(error.empty() ? std::string("an error without a message") : error);
    throw PeerFailure(error);  // not reached: check() throws for a failing process
}

void AgreeingGroup::minInPlace(std::span<float> values) {
    check({});
    inner_.minInPlace(values);
}

void AgreeingGroup::minInPlace(std::span<int32_t> values) {
    check({});
    inner_.minInPlace(values);
}

void AgreeingGroup::sumInPlace(std::span<float> values) {
    check({});
    inner_.sumInPlace(values);
}

std::vector<float> AgreeingGroup::gather(std::span<const float> values) {
    check({});
    return inner_.gather(values);
}

std::vector<std::vector<uint8_t>> AgreeingGroup::exchange(const std::vector<std::vector<uint8_t>>& sends) {
    check({});
    return inner_.exchange(sends);
}

}  // namespace flowsurf::methods
