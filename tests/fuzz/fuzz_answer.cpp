// libFuzzer: any bytes as a student's answer to the planar 2R's b11 and its equation of
// motion, and as an entry's name. Every check comes back with a verdict (never an
// exception); an unreadable answer's message is UTF-8 and points at a character of the
// answer or just after it.
#include <cstdint>
#include <string>

#include "core/io/scene_file.hpp"
#include "core/model/utf8_text.hpp"
#include "core/pipeline/answer_check.hpp"
#include "fuzz_support.hpp"

int ll::fuzz::answer(const std::uint8_t* data, std::size_t size) {
    static const auto key = ll::AnswerKey::build(ll::loadScene(LL_EXAMPLES_DIR "/planar_2r.json").scene);
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t characters = ll::characterCount(text, text.size());
    for (const char* entry : {"b11", "equation1", "c121"}) {
        const ll::AnswerCheck c = key->check({entry, text, true});
        if (c.verdict == ll::AnswerVerdict::Unreadable) {
            ll::fuzz::require(isValidUtf8(c.problem.english()), "a problem that is not UTF-8");
            ll::fuzz::require(c.position <= characters + 1, "a position past the answer's end");
        } else {
            ll::fuzz::require(!c.readAs.empty(), "an answer judged without what was read");
        }
    }
    const ll::AnswerCheck byName = key->check({text, "0"});
    ll::fuzz::require(byName.verdict != ll::AnswerVerdict::Unreadable || !byName.problem.empty(), "an unknown entry without a message");
    return 0;
}
