#pragma once
// JSON written as it is produced, byte for byte in the layout of nlohmann's dump(2)
// (two-space indents, "key": value, [] and {} when empty, UTF-8 kept as is) or, Compact,
// of its dump() (no spaces, no line breaks): the derivation's JSON is tens of megabytes
// for an expanded 7-joint arm, which a nlohmann document would hold twice. Strings are
// checked to be UTF-8 as nlohmann checks them: anything else throws
// std::invalid_argument naming the byte.
#include <string>
#include <string_view>
#include <vector>

namespace ll::present {

class JsonWriter {
public:
    enum class Layout { Indented, Compact };
    explicit JsonWriter(std::string& out, Layout layout = Layout::Indented) : out_(out), compact_(layout == Layout::Compact) {}

    void beginObject() { open('{', true); }
    void endObject() { close('}'); }
    void beginArray() { open('[', false); }
    void endArray() { close(']'); }
    // The next member of the open object; its value follows.
    void key(std::string_view name);

    void value(std::string_view s);
    void value(const char* s) { value(std::string_view(s)); }
    void value(long long n);
    void value(int n) { value(static_cast<long long>(n)); }
    void value(double x);  // as nlohmann prints it: 0.008, 1e-05, 2.0
    void value(bool b);
    void value(const std::vector<std::string>& strings);  // an array of them
    // key(name), then value(v).
    template <class T>
    void member(std::string_view name, const T& v) {
        key(name);
        value(v);
    }
    // s as a JSON string, quotes included, appended to `out`. Throws
    // std::invalid_argument when s is not UTF-8.
    static void quote(std::string_view s, std::string& out);

    // Whole, every object and array closed.
    bool complete() const { return levels_.empty() && started_; }

private:
    struct Level {
        bool object;
        bool empty = true;
    };
    void open(char bracket, bool object);
    void close(char bracket);
    void beforeValue();
    void newline();

    std::string& out_;
    bool compact_;
    std::vector<Level> levels_;
    bool afterKey_ = false;
    bool started_ = false;
};

}  // namespace ll::present
