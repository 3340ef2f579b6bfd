// SPDX-License-Identifier: MIT
#include "window.h"

#include <imgui.h>
#include "imgui_backends.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "panels/panel_style.h"
#include "platform.h"
#include "state/glyphs.h"

namespace hsr::viz {
namespace {

// The style before scaling (ScaleAllSizes multiplies, so each scale starts from this).
ImGuiStyle& unscaled_style() {
    static ImGuiStyle style;
    return style;
}

// Drawable pixels per window point: 2 in a browser page at devicePixelRatio 2 (the window's size is in CSS pixels),
// 1 where the window's size is in pixels (X11). Dear ImGui lays out in points and draws them this many pixels big.
float pixels_per_point() {
    SDL_Window* window = SDL_GL_GetCurrentWindow();
    int points = 0, pixels = 0, h = 0;
    if (!window) return 1;
    SDL_GetWindowSize(window, &points, &h);
    SDL_GL_GetDrawableSize(window, &pixels, &h);
    return points > 0 && pixels > 0 ? float(pixels) / float(points) : 1.0f;
}

}  // namespace

void load_fonts(ImGuiIO& io, float scale) {
    // The characters lessons may use (state/glyphs.h: `hsrviz check` warns about any other), as ImGui's ranges
    static const std::vector<ImWchar> ranges = [] {
        std::vector<ImWchar> r;
        for (const GlyphRange& g : font_glyphs) r.push_back(ImWchar(g.first)), r.push_back(ImWchar(g.last));
        r.push_back(0);
        return r;
    }();
    const char* sans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const char* mono = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
    if (!std::filesystem::exists(sans) || !std::filesystem::exists(mono)) {
        io.Fonts->AddFontDefault();  // ASCII only: ≤, → and ε will show as '?'
        return;
    }
    // rasterised for the drawable's pixels and shown at the size in points: sharp on a high-density screen
    const float density = pixels_per_point();
    io.FontGlobalScale = 1 / density;
    io.Fonts->AddFontFromFileTTF(sans, 17.0f * scale * density, nullptr, ranges.data());
    io.Fonts->AddFontFromFileTTF(mono, 15.0f * scale * density, nullptr, ranges.data());  // pseudocode
}

bool interactive(const AppOptions& o) { return !o.screenshot && !o.record_dir && !o.gif; }

bool Window::open(const AppOptions& o) {
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
        std::fprintf(stderr, "hsrviz: SDL_Init failed: %s\n", SDL_GetError());
        return false;
    }
    const GlProfile& profile = gl_profile();
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, profile.es ? SDL_GL_CONTEXT_PROFILE_ES : SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, profile.major);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, profile.minor);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
    // An interactive window opens as the last one closed (unless --size says otherwise); scripted ones at their size
    const bool remembered = interactive(o) && !o.size_given && !o.projector;
    const int width = remembered ? settings.width : o.width, height = remembered ? settings.height : o.height;
    const int x = remembered && settings.x ? *settings.x : int(SDL_WINDOWPOS_CENTERED);
    const int y = remembered && settings.y ? *settings.y : int(SDL_WINDOWPOS_CENTERED);
    // screenshots keep their size; a page fills the browser's window already (and a browser lets only a person's
    // click make it full screen)
    const bool fullscreen = o.projector && !o.screenshot && !o.record_dir && !gl_profile().browser_paced;
    window = SDL_CreateWindow("hsrviz", x, y, width, height,
                              SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI |
                                  (remembered && settings.maximized ? SDL_WINDOW_MAXIMIZED : 0) |
                                  (fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0));
    if (!window) {
        std::fprintf(stderr, "hsrviz: cannot open a window: %s\n", SDL_GetError());
        return false;
    }
    gl = SDL_GL_CreateContext(window);
    if (!gl) {
        std::fprintf(stderr, "hsrviz: cannot create an OpenGL%s %d.%d context: %s\n", profile.es ? " ES" : "", profile.major, profile.minor, SDL_GetError());
        return false;
    }
    SDL_GL_MakeCurrent(window, gl);
    if (!profile.browser_paced) SDL_GL_SetSwapInterval(1);
    return true;
}

void Window::close() {
    if (gl) SDL_GL_DeleteContext(gl);
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
}

void setup_imgui(const Window& w, const AppOptions& o) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    // a slider's grab is drawn under its number: a half-transparent one leaves every digit readable ("2.|00")
    for (const ImGuiCol c : {ImGuiCol_SliderGrab, ImGuiCol_SliderGrabActive}) ImGui::GetStyle().Colors[c].w = 0.45f;
    if (o.projector) {  // high contrast for a washed-out projector: white on black, bright frames
        ImGuiStyle& style = ImGui::GetStyle();
        style.Colors[ImGuiCol_Text] = ImVec4(1, 1, 1, 1);
        style.Colors[ImGuiCol_WindowBg] = ImVec4(0, 0, 0, 1);
        style.Colors[ImGuiCol_Border] = ImVec4(0.8f, 0.8f, 0.8f, 1);
        style.FrameBorderSize = 1, style.WindowBorderSize = 2;
    }
    unscaled_style() = ImGui::GetStyle();
    ImGui_ImplSDL2_InitForOpenGL(w.window, w.gl);
    ImGui_ImplOpenGL3_Init(gl_profile().glsl_version);
    apply_scale(initial_scale(o));
}

float initial_scale(const AppOptions& o) {
    if (o.scale > 0) return o.scale;
    if (o.projector) return 1.3f;
    float dpi = 0;
    // a dense screen whose window is sized in pixels (X11) needs larger type; one sized in points (a browser page at
    // devicePixelRatio 2) has it already
    if (SDL_GetDisplayDPI(0, &dpi, nullptr, nullptr) == 0 && dpi / pixels_per_point() >= 144)
        return std::min(dpi / 96 / pixels_per_point(), 3.0f);
    return 1.0f;
}

void apply_scale(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    ImGuiStyle& style = ImGui::GetStyle();
    style = unscaled_style();
    style.ScaleAllSizes(scale);
    io.Fonts->Clear();
    load_fonts(io, scale);
    type_scale() = scale;
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

}  // namespace hsr::viz
