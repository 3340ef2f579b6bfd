// SPDX-License-Identifier: MIT
// Checks that a screenshot of the window is a real picture: the expected size, a 3D view that is not just
// background, and panels with text. Usage: png_check FILE WIDTH HEIGHT
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include <gif_lib.h>

#include <stb/stb_image.h>

// png_check --ids FILE WIDTH HEIGHT ID…: a 16-bit grey id image of that size holding exactly the ids listed
// (0, the background, may also appear).
int check_ids(int argc, char** argv) {
    int w = 0, h = 0, n = 0;
    if (!stbi_is_16_bit(argv[2])) {
        std::fprintf(stderr, "png_check: %s is not a 16-bit PNG\n", argv[2]);
        return 1;
    }
    stbi_us* ids = stbi_load_16(argv[2], &w, &h, &n, 0);
    if (!ids || n != 1 || w != std::atoi(argv[3]) || h != std::atoi(argv[4])) {
        std::fprintf(stderr, "png_check: %s: want %sx%s grey, got %dx%d with %d channels\n", argv[2], argv[3], argv[4], w, h, n);
        return 1;
    }
    std::set<int> seen, want;
    for (int i = 0; i < w * h; ++i)
        if (ids[i] != 0) seen.insert(ids[i]);
    stbi_image_free(ids);
    for (int i = 5; i < argc; ++i) want.insert(std::atoi(argv[i]));
    std::printf("png_check: %s: ids", argv[2]);
    for (int id : seen) std::printf(" %d", id);
    std::printf("\n");
    return seen == want ? 0 : 1;
}

// png_check --same-ids A B MAX: two 16-bit id images of one size differ in at most MAX pixels
int same_ids(char** argv) {
    int wa = 0, ha = 0, na = 0, wb = 0, hb = 0, nb = 0;
    stbi_us* a = stbi_load_16(argv[2], &wa, &ha, &na, 1);
    stbi_us* b = stbi_load_16(argv[3], &wb, &hb, &nb, 1);
    if (!a || !b || wa != wb || ha != hb) {
        std::fprintf(stderr, "png_check: %s and %s cannot be compared\n", argv[2], argv[3]);
        return 1;
    }
    long differ = 0;
    for (long k = 0; k < long(wa) * ha; ++k) differ += a[k] != b[k];
    stbi_image_free(a);
    stbi_image_free(b);
    std::printf("png_check: %s and %s differ in %ld of %d pixels\n", argv[2], argv[3], differ, wa * ha);
    return differ <= std::atol(argv[4]) ? 0 : 1;
}

// An animated GIF decodes and has this many frames, each the size of the screen.
// --gif-frames FILE N [W H]: the GIF decodes, with N frames (each the size of the whole, W × H when given)
int gif_frames(int argc, char** argv) {
    int error = 0;
    GifFileType* gif = DGifOpenFileName(argv[2], &error);
    if (!gif || DGifSlurp(gif) == GIF_ERROR) {
        std::fprintf(stderr, "png_check: %s does not decode as a GIF (%s)\n", argv[2], GifErrorString(gif ? gif->Error : error));
        return 1;
    }
    const int frames = gif->ImageCount, want = std::atoi(argv[3]);
    const bool size_given = argc == 6;
    bool sizes = true;
    for (int i = 0; i < frames; ++i) sizes = sizes && gif->SavedImages[i].ImageDesc.Width == gif->SWidth && gif->SavedImages[i].ImageDesc.Height == gif->SHeight;
    std::printf("png_check: %s: %d frames of %dx%d\n", argv[2], frames, gif->SWidth, gif->SHeight);
    if (size_given) sizes = sizes && gif->SWidth == std::atoi(argv[4]) && gif->SHeight == std::atoi(argv[5]);
    DGifCloseFile(gif, &error);
    return frames == want && frames > 0 && sizes ? 0 : 1;
}

int main(int argc, char** argv) {
    if ((argc == 4 || argc == 6) && std::string(argv[1]) == "--gif-frames") return gif_frames(argc, argv);
    if (argc == 5 && std::string(argv[1]) == "--same-ids") return same_ids(argv);
    if (argc >= 5 && std::string(argv[1]) == "--ids") return check_ids(argc, argv);
    if (argc != 4) {
        std::fprintf(stderr, "usage: png_check FILE WIDTH HEIGHT\n");
        return 2;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(argv[1], &w, &h, &n, 3);
    if (!pixels) {
        std::fprintf(stderr, "png_check: cannot read %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    int failures = 0;
    if (w != std::atoi(argv[2]) || h != std::atoi(argv[3])) {
        std::fprintf(stderr, "png_check: %s is %dx%d, expected %sx%s\n", argv[1], w, h, argv[2], argv[3]);
        ++failures;
    }
    // Count pixels unlike the background colour (top-left corner) and distinct colours, in the 3D view (left
    // half) and in the panels (right third).
    const unsigned char* bg = pixels;
    long view_drawn = 0, panel_drawn = 0;
    std::set<int> colours;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned char* p = pixels + 3 * (std::size_t(y) * w + x);
            const bool drawn = std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 30;
            if (x < w / 2) view_drawn += drawn;
            if (x > 2 * w / 3) panel_drawn += drawn;
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
        }
    stbi_image_free(pixels);
    const long area = long(w) * h;
    std::printf("png_check: %s: %dx%d, %zu colours, %.2f%% of the view and %.2f%% of the panels drawn\n", argv[1], w, h,
                colours.size(), 200.0 * double(view_drawn) / double(area), 300.0 * double(panel_drawn) / double(area));
    if (colours.size() < 16) ++failures;
    if (view_drawn < area / 400) ++failures;   // at least 0.5% of the left half is scene
    if (panel_drawn < area / 100) ++failures;  // at least 3% of the right third is panel and text
    if (failures) std::fprintf(stderr, "png_check: %s looks blank or wrong\n", argv[1]);
    return failures ? 1 : 0;
}
