// SPDX-License-Identifier: MIT
#include "state/chapters.h"

namespace hsr::viz {

Texts read_texts(const algo::TomlReader& r, const toml::node* n, const std::string& field, const std::vector<std::string>& languages) {
    Texts t;
    if (!n) return t;
    if (const auto s = n->value<std::string>()) {  // one text: the default language's
        t[languages.front()] = *s;
        return t;
    }
    const toml::table* table = n->as_table();
    if (!table) r.fail(n, field, "expected a text, or a table of texts by language ({ en = \"…\", de = \"…\" })");
    for (const auto& [key, value] : *table) {
        const std::string lang(key.str());
        if (std::find(languages.begin(), languages.end(), lang) == languages.end())
            r.fail(&value, field + "." + lang, "a language the lesson does not list in languages = [...]");
        const auto s = value.value<std::string>();
        if (!s) r.fail(&value, field + "." + lang, "expected a text");
        t[lang] = *s;
    }
    return t;
}

namespace {

EventPattern read_pattern(const algo::TomlReader& r, const toml::table& t, std::string_view kind_key, const std::string& field) {
    EventPattern p{r.text(t, kind_key, field), {}};
    if (const toml::node* m = t.get("match")) {
        const toml::table* table = m->as_table();
        if (!table) r.fail(m, field + ".match", "expected a table of field = value");
        for (const auto& [key, value] : *table) {
            std::string text;
            if (const auto s = value.value<std::string>()) text = *s;
            else if (const auto i = value.value_exact<std::int64_t>()) text = std::to_string(*i);
            else if (const auto b = value.value<bool>()) text = *b ? "true" : "false";
            else r.fail(&value, field + ".match." + std::string(key.str()), "expected a text, a whole number or true/false");
            p.match.push_back({std::string(key.str()), text});
        }
    }
    return p;
}

}  // namespace

std::vector<Chapter> read_chapters(const algo::TomlReader& r, const toml::table& root, std::vector<std::string>& languages) {
    languages = r.strings(root, "languages", "");
    if (languages.empty()) languages = {"en"};
    std::vector<Chapter> out;
    const toml::array* chapters = r.array(root, "chapters", "", false);
    if (!chapters) return out;
    for (std::size_t i = 0; i < chapters->size(); ++i) {
        const std::string f = algo::index("chapters", i);
        const toml::table* t = chapters->get(i)->as_table();
        if (!t) r.fail(chapters->get(i), f, "expected a table");
        r.only_keys(*t, f, {"title", "when", "match", "step", "pause", "opens", "narration", "question"});
        Chapter c;
        c.line = int(t->source().begin.line);
        c.titles = read_texts(r, t->get("title"), algo::join(f, "title"), languages);
        c.title = in_language(c.titles, languages.front(), languages);
        c.narration = read_texts(r, t->get("narration"), algo::join(f, "narration"), languages);
        c.pause = r.boolean(*t, "pause", f, false);
        c.opens = r.boolean(*t, "opens", f, false);
        if (t->contains("when")) c.when = read_pattern(r, *t, "when", f);
        if (t->contains("step")) {
            const auto s = r.integer(*t, "step", f);
            if (s < 0) r.fail(t->get("step"), algo::join(f, "step"), "expected a step from 0");
            c.step = std::size_t(s);
        }
        if (c.when.has_value() == c.step.has_value()) r.fail(t, f, "a chapter needs when = \"EventKind\" or step = N (one of them)");
        if (const toml::node* qn = t->get("question")) {
            const std::string fq = algo::join(f, "question");
            const toml::table* q = qn->as_table();
            if (!q) r.fail(qn, fq, "expected a table");
            r.only_keys(*q, fq, {"ask", "event", "match", "field", "choices"});
            Question question;
            question.line = int(q->source().begin.line);
            question.ask = read_texts(r, q->get("ask"), algo::join(fq, "ask"), languages);
            if (question.ask.empty()) r.fail(q, algo::join(fq, "ask"), "a question needs ask = \"…\"");
            question.answer_event = read_pattern(r, *q, "event", fq);
            question.field = r.text(*q, "field", fq);
            question.choices = r.strings(*q, "choices", fq);
            if (question.choices.size() > 9) r.fail(q->get("choices"), algo::join(fq, "choices"), "at most 9 choices (keys 1 to 9)");
            c.question = std::move(question);
        }
        out.push_back(std::move(c));
    }
    return out;
}

std::string value_text(const nlohmann::json& v) {
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

bool fits(const nlohmann::json& e, const EventPattern& p) {
    if (!e.contains("kind") || e["kind"] != p.kind) return false;
    for (const auto& [key, value] : p.match)
        if (!e.contains(key) || value_text(e[key]) != value) return false;
    return true;
}

std::string in_language(const Texts& t, const std::string& language, const std::vector<std::string>& languages) {
    if (const auto it = t.find(language); it != t.end()) return it->second;
    if (!languages.empty())
        if (const auto it = t.find(languages.front()); it != t.end()) return it->second;
    return t.empty() ? std::string() : t.begin()->second;
}

}  // namespace hsr::viz
