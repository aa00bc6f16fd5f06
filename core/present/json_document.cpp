#include "core/present/json_document.hpp"

#include "core/present/json_writer.hpp"
#include "core/present/latex_document.hpp"
#include "core/present/message_text.hpp"
#include "core/present/text_document.hpp"

namespace ll::present {
namespace {

// A value's Plain: a matrix as rows of entries (a column as a list).
void writePlain(JsonWriter& json, const DisplayNode& value) {
    if (value.kind != DisplayKind::Matrix) return json.value(renderDisplay(value, DisplayStyle::Plain));
    json.beginArray();
    for (const auto& r : value.rows) {
        if (r.size() == 1) {
            json.value(renderDisplay(*r[0], DisplayStyle::Plain));
            continue;
        }
        json.beginArray();
        for (const DisplayPtr& c : r) json.value(renderDisplay(*c, DisplayStyle::Plain));
        json.endArray();
    }
    json.endArray();
}

}  // namespace

std::string jsonDocument(const DisplayDocument& document, const ModelSummary& model) {
    std::string out;
    JsonWriter json(out);
    json.beginObject();
    json.member("system", document.systemName);
    json.member("mode", model.mode);
    if (!document.form.empty()) {
        json.member("form", messageText(document.form, document.language));
        json.member("form_reason", messageText(document.formReason, document.language));
    }
    json.member("coordinates", document.coordinateNames);
    json.key("steps");
    json.beginArray();
    for (const DisplayStep& step : document.steps) {
        json.beginObject();
        json.member("number", step.number);
        json.member("title", messageText(step.title, document.language));
        json.key("formula");
        json.beginObject();
        json.member("text", step.formulaText);
        json.member("latex", step.formulaLatex);
        json.endObject();
        json.member("seconds", step.seconds);
        json.key("items");
        json.beginArray();
        for (const DisplayItem& item : step.items) {
            json.beginObject();
            json.member("name", item.name);
            json.member("latex", itemLatex(item));
            json.member("text", itemText(item, document.language));
            json.key("expr");
            if (item.quantity == Quantity::EquationOfMotion || item.quantity == Quantity::ClosedLoop)  // an equation: both sides
                json.value(renderDisplay(*item.equation, DisplayStyle::Plain));
            else writePlain(json, *item.value);
            json.endObject();
        }
        json.endArray();
        json.endObject();
    }
    json.endArray();
    for (const auto& [name, value] :
         {std::pair{"B", &model.B}, {"C", &model.C}, {"g", &model.g}, {"Q", &model.Q}, {"Ekin", &model.Ekin}, {"Epot", &model.Epot}}) {
        json.key(name);
        writePlain(json, **value);
    }
    json.member("actuated", model.actuated);
    json.member("underactuated", model.underactuated);
    json.member("warnings", model.warnings);
    json.endObject();
    return out + '\n';
}

}  // namespace ll::present
