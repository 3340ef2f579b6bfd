// SPDX-License-Identifier: MIT
// The window's settings file and its neighbours (HSRVIZ_CONFIG=…): a FIFO or a link at a temporary name, a link at the
// path (dangling or not), an existing .bak, a lesson, notes that are not TOML, a broken file of hsrviz's own, a folder,
// 70 KB, six bad practice records. The window runs (--keys ] widens the panel column, so it saves), says what it
// left alone, and afterwards every file not hsrviz's is as it was.
#include <sys/stat.h>

#include <fstream>

#include "catalogue.h"

namespace bad_inputs {
namespace {

const std::string ours = "# hsrviz remembers the window here between runs; delete the file to start afresh.\n";
const std::string notes = "my notes, not TOML: [\n";

// The window saving its settings to `config` (a name in the case's folder).
Run window_saving(const std::string& config, int exit, std::vector<std::string> says) {
    Run r{{"s.toml", "--keys", "],]", "--screenshot", "w.png", "--frames", "3", "--size", "640x400"}, exit, std::move(says)};
    r.env = "HSRVIZ_CONFIG=\"$PWD/" + config + "\"";
    return r;
}

// "" when the file `name` in `dir` holds `text`, else why not.
std::string holds(const fs::path& dir, const std::string& name, const std::string& text) {
    if (fs::is_symlink(dir / name)) return "";
    return read(dir / name) == text ? "" : name + " was changed";
}

}  // namespace

std::vector<Case> settings_cases() {
    std::vector<Case> cs;
    const auto add = [&](const std::string& name, std::map<std::string, std::string> files, std::function<void(const fs::path&)> make,
                         Run run, std::function<std::string(const fs::path&)> after) {
        files["s.toml"] = scene;
        cs.push_back(Case{"settings: " + name, std::move(files), std::move(make), {std::move(run)}, std::move(after)});
    };
    add("a FIFO at window.toml.new", {}, [](const fs::path& d) { mkfifo((d / "window.toml.new").c_str(), 0600); },
        window_saving("window.toml", 0, {}), [](const fs::path& d) -> std::string {
            if (!fs::is_fifo(d / "window.toml.new")) return "the FIFO is gone";
            return read(d / "window.toml").rfind(ours, 0) == 0 ? "" : "the settings were not saved";
        });
    add("a link to a lesson at window.toml.new", {{"l.toml", lesson}}, [](const fs::path& d) { fs::create_symlink("l.toml", d / "window.toml.new"); },
        window_saving("window.toml", 0, {}), [](const fs::path& d) -> std::string {
            if (const std::string why = holds(d, "l.toml", lesson); !why.empty()) return why;
            return fs::is_symlink(d / "window.toml") ? "window.toml became a link" : "";
        });
    add("the path a link to a lesson", {{"l.toml", lesson}}, [](const fs::path& d) { fs::create_symlink("l.toml", d / "window.toml"); },
        window_saving("window.toml", 0, {"window.toml is a symbolic link; it is left alone"}),
        [](const fs::path& d) { return fs::is_symlink(d / "window.toml") ? holds(d, "l.toml", lesson) : "the link was replaced"; });
    add("the path a dangling link", {}, [](const fs::path& d) { fs::create_symlink("gone.toml", d / "window.toml"); },
        window_saving("window.toml", 0, {"settings are not saved there"}), [](const fs::path& d) -> std::string {
            if (!fs::is_symlink(fs::symlink_status(d / "window.toml"))) return "the link was replaced";
            return fs::exists(d / "gone.toml") ? "the link's target was made" : "";
        });
    add("notes that are not TOML, with a .bak of their own", {{"notes.txt", notes}, {"notes.txt.bak", "older notes\n"}}, {},
        window_saving("notes.txt", 0, {"notes.txt:1:", "left alone"}), [](const fs::path& d) {
            const std::string why = holds(d, "notes.txt", notes);
            return why.empty() ? holds(d, "notes.txt.bak", "older notes\n") : why;
        });
    add("a lesson", {{"l.toml", lesson}}, {}, window_saving("l.toml", 0, {"is not an hsrviz settings file (it has"}),
        [](const fs::path& d) { return holds(d, "l.toml", lesson); });
    add("a half-saved lesson (not TOML)", {{"l.toml", lesson.substr(0, 40)}}, {}, window_saving("l.toml", 0, {"l.toml:", "left alone"}),
        [](const fs::path& d) { return fs::exists(d / "l.toml.bak") ? "moved to .bak" : holds(d, "l.toml", lesson.substr(0, 40)); });
    add("a broken file of hsrviz's, .bak free", {{"window.toml", ours + "width = [1\n"}}, {}, window_saving("window.toml", 0, {"kept as"}),
        [](const fs::path& d) { return holds(d, "window.toml.bak", ours + "width = [1\n"); });
    add("a broken file of hsrviz's, and a .bak there", {{"window.toml", ours + "width = [1\n"}, {"window.toml.bak", "older\n"}}, {},
        window_saving("window.toml", 0, {"window.toml.bak exists already"}), [](const fs::path& d) {
            const std::string why = holds(d, "window.toml.bak", "older\n");
            return why.empty() ? holds(d, "window.toml", ours + "width = [1\n") : why;
        });
    add("a folder", {}, [](const fs::path& d) { fs::create_directory(d / "window.toml"); }, window_saving("window.toml", 0, {"is a folder"}),
        [](const fs::path& d) { return fs::is_directory(d / "window.toml") ? "" : "the folder is gone"; });
    add("a FIFO", {}, [](const fs::path& d) { mkfifo((d / "window.toml").c_str(), 0600); }, window_saving("window.toml", 0, {"FIFO"}),
        [](const fs::path& d) { return fs::is_fifo(d / "window.toml") ? "" : "the FIFO is gone"; });
    add("70 KB", {{"window.toml", ours + "# " + std::string(70 << 10, 'x') + "\n"}}, {}, window_saving("window.toml", 0, {"is 71 KB; hsrviz reads files up to 64 KB"}),
        {});
    add("empty", {{"window.toml", ""}}, {}, window_saving("window.toml", 0, {}),
        [](const fs::path& d) { return read(d / "window.toml").rfind(ours, 0) == 0 ? "" : "the settings were not saved"; });
    std::string records;
    for (const char* topic : {"a", "b", "c", "d", "e", "f"}) records += std::string("[practice.") + topic + "]\nanswered = 1\nright = 5\nbest_streak = 0\n";
    add("six bad practice records", {{"window.toml", records}}, {},
        window_saving("window.toml", 0, {"'practice.a'", "'practice.b'", "'practice.c'", "'practice.d'", "'practice.e'", "'practice.f'",
                                         "kept in the file as it is"}),
        [](const fs::path& d) -> std::string {  // all six vanished from the file when it was saved
            const std::string saved = read(d / "window.toml");
            if (saved.rfind(ours, 0) != 0) return "the settings were not saved";
            for (const char* topic : {"a", "b", "c", "d", "e", "f"})
                if (saved.find(std::string("[practice.") + topic + "]") == std::string::npos) return std::string("practice.") + topic + " was lost";
            return "";
        });
    return cs;
}

}  // namespace bad_inputs
