#include "anim/contact_sheet.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "anim/statistics.h"
#include "image/png_writer.h"
#include "util/durable_file.h"

namespace frameray::anim {

namespace fs = std::filesystem;

namespace {

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (size_t k = 0; k < 3; ++k)
            v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

std::string escapeHtml(std::string_view text) {
    std::string out;
    for (const char c : text) switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    return out;
}

// A JSON string that is safe inside <script> too.
std::string scriptString(const std::string& text) {
    std::string s = jsonString(text);
    for (size_t at = s.find("</"); at != std::string::npos; at = s.find("</", at + 3))
        s.replace(at, 2, "<\\/");
    return s;
}

// "12 345 678": thin groups, easier to read than a run of digits.
std::string grouped(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i && (digits.size() - i) % 3 == 0) out += ' ';
        out += digits[i];
    }
    return out;
}

std::string_view stateName(SheetFrame::State s) {
    switch (s) {
        case SheetFrame::State::Rendered:
            return "rendered";
        case SheetFrame::State::Kept:
            return "kept";
        case SheetFrame::State::Failed:
            return "failed";
        case SheetFrame::State::Pending:
            break;
    }
    return "pending";
}

// Frames the browser can show from the file itself in the large view.
bool browserShows(const std::string& file) {
    const std::string ext = fs::path(file).extension().string();
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp";
}

std::string cellHtml(const SheetFrame& f, size_t index) {
    std::string meta = fmt::format("frame {} &middot; clock {:.6g}", f.number, f.clock);
    switch (f.state) {
        case SheetFrame::State::Rendered:
            meta += fmt::format("<br>{:.2f} s &middot; {} rays", f.seconds, grouped(f.rays));
            break;
        case SheetFrame::State::Kept:
            meta += "<br>kept (an earlier run)";
            break;
        case SheetFrame::State::Failed:
            meta += "<br><b>failed</b>";
            break;
        case SheetFrame::State::Pending:
            meta += "<br>not rendered yet";
            break;
    }
    const std::string picture =
        f.thumbnailPng.empty()
            ? std::string("<div class=\"ph\"></div>")
            : fmt::format("<img src=\"data:image/png;base64,{}\" alt=\"frame {}\">",
                          base64(f.thumbnailPng), f.number);
    return fmt::format(
        "<div class=\"cell {}\" data-index=\"{}\" data-frame=\"{}\"{}>{}<div "
        "class=\"meta\">{}</div></div>\n",
        stateName(f.state), index, f.number,
        f.failure.empty() ? std::string() : " title=\"" + escapeHtml(f.failure) + "\"", picture,
        meta);
}

constexpr std::string_view kStyle = R"(<style>
body{margin:0;padding:16px;background:#1b1b1b;color:#ddd;font:13px sans-serif}
h1{font-size:16px;font-weight:normal;margin:0 0 10px}
#player{margin-bottom:16px}
#view{width:480px;min-height:60px;background:#000;display:block}
#controls{margin-top:6px}
#controls button{background:#333;color:#ddd;border:1px solid #555;padding:2px 10px}
#scrub{width:300px;vertical-align:middle}
#grid{display:flex;flex-wrap:wrap;gap:8px}
.cell{width:160px;background:#262626;padding:4px;border:2px solid #262626;cursor:pointer}
.cell img{width:160px;display:block}
.cell .ph{width:160px;height:120px;background:#3a3a3a}
.cell.failed{border-color:#d02020}
.cell.failed .ph{background:#5a1010}
.cell.current{border-color:#e0b000}
.meta{font-size:11px;line-height:1.35;margin-top:3px}
</style>
)";

// The player: steps through the frames that have a picture.
constexpr std::string_view kScript = R"(
const cells = Array.from(document.querySelectorAll('.cell'));
const playable = cells.filter(c => c.querySelector('img'));
const view = document.getElementById('view');
const label = document.getElementById('current');
const scrub = document.getElementById('scrub');
let at = 0, timer = null;
scrub.max = Math.max(0, playable.length - 1);
function show(i) {
  if (!playable.length) { label.textContent = 'no frame yet'; return; }
  at = (i % playable.length + playable.length) % playable.length;
  cells.forEach(c => c.classList.remove('current'));
  const cell = playable[at], f = frames[Number(cell.dataset.index)];
  cell.classList.add('current');
  const thumb = cell.querySelector('img').src;
  view.onerror = () => { view.onerror = null; view.src = thumb; };
  view.src = f.browser ? f.file : thumb;
  label.textContent = 'frame ' + f.n + ' \u00b7 clock ' + f.clock + ' \u00b7 ' + f.state;
  label.dataset.frame = f.n;
  scrub.value = at;
}
function step(k) { show(at + k); }
function play() {
  if (timer) { clearInterval(timer); timer = null; }
  else timer = setInterval(() => step(1), 1000 / fps);
  document.getElementById('play').textContent = timer ? 'pause' : 'play';
}
document.getElementById('prev').onclick = () => step(-1);
document.getElementById('next').onclick = () => step(1);
document.getElementById('play').onclick = play;
scrub.oninput = () => show(Number(scrub.value));
cells.forEach(c => c.onclick = () => { const i = playable.indexOf(c); if (i >= 0) show(i); });
document.onkeydown = e => {
  if (e.key === 'ArrowRight') step(1);
  else if (e.key === 'ArrowLeft') step(-1);
  else if (e.key === ' ') { play(); e.preventDefault(); }
};
const query = new URLSearchParams(location.search);
let start = 0;
if (query.has('frame')) {
  const n = Number(query.get('frame'));
  start = Math.max(0, playable.findIndex(c => frames[Number(c.dataset.index)].n === n));
}
show(start);
for (let k = Number(query.get('step') || 0); k > 0; --k) step(1);
</script>
)";

}  // namespace

std::string contactSheetHtml(const std::string& title, const std::vector<SheetFrame>& frames,
                             double fps) {
    size_t done = 0, failed = 0;
    for (const SheetFrame& f : frames) {
        done += f.state == SheetFrame::State::Rendered || f.state == SheetFrame::State::Kept;
        failed += f.state == SheetFrame::State::Failed;
    }
    std::string page = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>{} - contact "
        "sheet</title>\n{}</head><body>\n<h1>{}: {} of {} frames{}</h1>\n",
        escapeHtml(title), kStyle, escapeHtml(title), done, frames.size(),
        failed ? fmt::format(", {} failed", failed) : std::string());
    page +=
        "<div id=\"player\"><img id=\"view\" alt=\"\"><div id=\"controls\"><button "
        "id=\"prev\">&#9664;</button> <button id=\"play\">play</button> <button "
        "id=\"next\">&#9654;</button> <input id=\"scrub\" type=\"range\" min=\"0\" max=\"0\" "
        "value=\"0\"> <span id=\"current\"></span></div></div>\n<div id=\"grid\">\n";
    for (size_t i = 0; i < frames.size(); ++i) page += cellHtml(frames[i], i);
    page += fmt::format("</div>\n<script>\nconst fps = {};\nconst frames = [\n", fps);
    for (const SheetFrame& f : frames)
        page += fmt::format("{{n:{},clock:{},file:{},state:\"{}\",browser:{}}},\n", f.number,
                            scriptString(fmt::format("{:.6g}", f.clock)), scriptString(f.file),
                            stateName(f.state), browserShows(f.file) ? "true" : "false");
    page += "];";
    page += kScript;
    page += "</body></html>\n";
    return page;
}

Rgb8Image contactSheetGrid(const std::vector<SheetFrame>& frames, int columns) {
    constexpr int kGap = 4;
    constexpr std::uint8_t kBackground = 27, kMissing = 58;
    columns = std::max(1, std::min<int>(columns, static_cast<int>(frames.size())));
    const int rows = static_cast<int>((frames.size() + columns - 1) / columns);
    int cellW = 1, cellH = 1;
    for (const SheetFrame& f : frames) {
        cellW = std::max(cellW, f.thumbnail.width);
        cellH = std::max(cellH, f.thumbnail.height);
    }
    if (cellW == 1 && cellH == 1) cellW = kThumbnailWidth, cellH = kThumbnailHeight;
    Rgb8Image grid;
    grid.width = columns * (cellW + kGap) + kGap;
    grid.height = rows * (cellH + kGap) + kGap;
    grid.rgb.assign(static_cast<size_t>(grid.width) * grid.height * 3, kBackground);
    for (size_t i = 0; i < frames.size(); ++i) {
        const SheetFrame& f = frames[i];
        const int x0 = kGap + static_cast<int>(i % columns) * (cellW + kGap);
        const int y0 = kGap + static_cast<int>(i / columns) * (cellH + kGap);
        const bool picture = !f.thumbnail.empty();
        const int w = picture ? f.thumbnail.width : cellW, h = picture ? f.thumbnail.height : cellH;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::uint8_t* out =
                    &grid.rgb[(static_cast<size_t>(y0 + y) * grid.width + x0 + x) * 3];
                if (picture) {
                    std::copy_n(&f.thumbnail.rgb[(static_cast<size_t>(y) * w + x) * 3], 3, out);
                } else if (f.state == SheetFrame::State::Failed) {
                    out[0] = 200, out[1] = 30, out[2] = 30;
                } else {
                    std::fill_n(out, 3, kMissing);
                }
            }
    }
    return grid;
}

ContactSheet::ContactSheet(const Sequence& seq, double fps) : name_(seq.sheetName), fps_(fps) {
    const fs::path folder = seq.frames.front().output.parent_path();
    folder_ = folder.empty() ? fs::path(".") : folder;
    if (seq.frames.size() <= kMaxListed)
        for (const FrameSpec& f : seq.frames) slot(f);
}

SheetFrame& ContactSheet::slot(const FrameSpec& frame) {
    SheetFrame& f = frames_[frame.number];
    f.number = frame.number;
    f.clock = frame.clock;
    f.file = frame.output.filename().string();
    return f;
}

namespace {

void setThumbnail(SheetFrame& f, const Rgb8Image& image) {
    f.thumbnail = shrinkToFit(image, kThumbnailWidth, kThumbnailHeight);
    const std::vector<unsigned char> png =
        image::encodePng(f.thumbnail.width, f.thumbnail.height, 3, 8, f.thumbnail.rgb.data());
    f.thumbnailPng.assign(png.begin(), png.end());
}

}  // namespace

void ContactSheet::rendered(const FrameSpec& frame, double seconds, std::uint64_t rays,
                            const Rgb8Image& thumbnail) {
    SheetFrame& f = slot(frame);
    f.state = SheetFrame::State::Rendered;
    f.seconds = seconds;
    f.rays = rays;
    if (!thumbnail.empty()) setThumbnail(f, thumbnail);
}

void ContactSheet::kept(const FrameSpec& frame) {
    SheetFrame& f = slot(frame);
    f.state = SheetFrame::State::Kept;
    try {
        setThumbnail(f, readRgb8(frame.output));
    } catch (const std::exception&) {
        // The journal verified the file; one that cannot be decoded here
        // (an unusual type) is listed without a picture.
    }
}

void ContactSheet::failed(const FrameSpec& frame, const std::string& why) {
    SheetFrame& f = slot(frame);
    f.state = SheetFrame::State::Failed;
    f.failure = why;
}

void ContactSheet::save(bool final) {
    const auto now = std::chrono::steady_clock::now();
    if (!final && lastSave_ && now - *lastSave_ < std::chrono::seconds(2)) return;
    lastSave_ = now;
    std::vector<SheetFrame> frames;
    frames.reserve(frames_.size());
    for (const auto& [number, f] : frames_) frames.push_back(f);
    util::replaceFileDurably(pagePath(), contactSheetHtml(name_, frames, fps_));
    // About 4:3 overall for 4:3 frames.
    const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(frames.size() * 1.0))));
    const Rgb8Image grid = contactSheetGrid(frames, columns);
    const std::vector<unsigned char> png =
        image::encodePng(grid.width, grid.height, 3, 8, grid.rgb.data());
    util::replaceFileDurably(
        gridPath(), std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace frameray::anim
