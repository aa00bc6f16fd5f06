#include "core/io/scene_json.hpp"

#include <algorithm>
#include <set>
#include <string_view>

#include "core/model/utf8_text.hpp"

namespace ll::scene_json {

namespace {

// nlohmann keeps the last of two equal keys without a word; the parser callback sees
// every key, so it reports the duplicates (with their paths) instead.
class DuplicateKeyFinder {
public:
    explicit DuplicateKeyFinder(std::vector<Diagnostic>& out) : out_(out) {}

    bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                levels_.push_back({event == Json::parse_event_t::object_start, enterElement(), {}, {}, 0});
                break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end: levels_.pop_back(); break;
            case Json::parse_event_t::key: {
                Level& level = levels_.back();
                level.key = parsed.get<std::string>();
                if (!level.keys.insert(level.key).second)
                    out_.push_back({Severity::Error, child(level.path, level.key), MessageId::KeyGivenTwice});
                break;
            }
            case Json::parse_event_t::value: enterElement(); break;
        }
        return true;
    }

private:
    struct Level {
        bool object;
        std::string path;
        std::set<std::string> keys;
        std::string key;        // object: the key whose value comes next
        std::size_t count = 0;  // array: elements so far
    };

    std::string enterElement() {
        if (levels_.empty()) return "";
        Level& level = levels_.back();
        return level.object ? child(level.path, level.key) : item(level.path, level.count++);
    }

    std::vector<Diagnostic>& out_;
    std::vector<Level> levels_;
};

// Columns count characters, as an editor shows them.
std::pair<std::size_t, std::size_t> lineAndColumn(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i)
        if (text[i] == '\n') ++line, lineStart = i + 1;
    return {line, characterCount(std::string_view(text).substr(lineStart), offset - lineStart) + 1};
}

Message at(const std::string& text, std::size_t offset) {
    const auto [line, column] = lineAndColumn(text, offset);
    return message(MessageId::AtLineColumn, line, column);
}

}  // namespace

Json parseJson(const std::string& text, std::vector<Diagnostic>& duplicates) {
    for (std::size_t i = 0; i < text.size();) {
        const Utf8Char c = decodeUtf8(text, i);
        if (!c.valid) throw InputError(kDocument, message(MessageId::FileNotUtf8, describeCharacter(c, text, i), at(text, i)));
        i += c.bytes;
    }
    Json root;
    try {
        root = Json::parse(text, DuplicateKeyFinder(duplicates));
    } catch (const Json::parse_error& e) {
        // what() is "[json.exception.parse_error.101] parse error at line L, column C:
        // syntax error while parsing value - <reason>"; keep <reason>, place it ourselves
        // (e.byte is 1-based: the character that could not be read).
        std::string reason = e.what();
        const std::size_t dash = reason.find(" - ");
        if (dash != std::string::npos) reason = reason.substr(dash + 3);
        // "last read: '<everything since the token began>'" can be a whole description:
        // keep its last 40 bytes (whole characters), so the message stays one short line.
        const std::size_t read = reason.find("last read: '");
        const std::size_t quoted = read == std::string::npos ? read : read + 12;
        if (quoted != std::string::npos && reason.size() > quoted + 60) {
            std::size_t from = reason.size() - 41;
            while (from < reason.size() && (static_cast<unsigned char>(reason[from]) & 0xC0) == 0x80) ++from;
            reason = reason.substr(0, quoted) + "..." + reason.substr(from);
        }
        throw InputError(kDocument, message(MessageId::JsonSyntaxError, at(text, e.byte > 0 ? e.byte - 1 : 0), reason));
    } catch (const Json::out_of_range& e) {
        // "number overflow parsing '1e400'" has no position; find the number.
        std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        if (open != std::string::npos && close > open) {
            const std::string number = what.substr(open + 1, close - open - 1);
            const std::size_t offset = text.find(number);
            const Message where = at(text, offset == std::string::npos ? 0 : offset);
            throw InputError(kDocument, message(MessageId::JsonNumberOutOfRange, where, number));
        }
        throw InputError(kDocument, message(MessageId::JsonError, e.what()));
    } catch (const Json::exception& e) {
        throw InputError(kDocument, message(MessageId::JsonError, e.what()));
    }
    if (!root.is_object())
        throw InputError(kDocument, message(MessageId::JsonExpectedGot, Message(MessageId::WantedTopLevelObject), describe(root)));
    return root;
}

// nlohmann's dump(2) gives every array element its own line; [x, y, z] and small
// entries such as {"joint": 1, "coefficient": 0.1} read better on one.
void writePretty(std::string& out, const Json& value, std::size_t indent) {
    if (!value.is_structured()) {
        out += value.dump();
        return;
    }
    const bool object = value.is_object();
    const std::string open = object ? "{" : "[", close = object ? "}" : "]";
    if (value.empty()) {
        out += open + close;
        return;
    }
    bool flat = true;
    for (const auto& element : value) flat = flat && !element.is_structured();
    if (flat) {
        std::string line = open;
        for (auto element = value.begin(); element != value.end(); ++element) {
            if (element != value.begin()) line += ", ";
            if (object) line += Json(element.key()).dump() + ": ";
            line += element->dump();
        }
        line += close;
        if (indent + line.size() <= 90) {
            out += line;
            return;
        }
    }
    out += open;
    for (auto element = value.begin(); element != value.end(); ++element) {
        out += (element == value.begin() ? "\n" : ",\n") + std::string(indent + 2, ' ');
        if (object) out += Json(element.key()).dump() + ": ";
        writePretty(out, *element, indent + 2);
    }
    out += "\n" + std::string(indent, ' ') + close;
}

}  // namespace ll::scene_json
