// The documentation is checked like code: every relative link in README.md and docs/*.md points
// at a file of the repository (and at a heading, when it names one), README stays a page a
// newcomer reads in two minutes, and docs/timings.md documents exactly the keys, with their
// types, that `vct render --timings` writes.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/frame_passes.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::path(VCT_SOURCE_DIR).lexically_normal();

std::string readText(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

bool isFence(const std::string& line) {
    const std::size_t first = line.find_first_not_of(' ');
    return first != std::string::npos && first <= 3 &&
           (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0);
}

// The lines of a markdown file with fenced code blocks emptied (so `# comment` in a shell block
// is no heading and `[i](j)` in code no link); line numbers are kept.
std::vector<std::string> linesOutsideCode(const std::string& text) {
    std::vector<std::string> lines = splitLines(text);
    bool inFence = false;
    for (std::string& line : lines) {
        if (isFence(line)) {
            inFence = !inFence;
            line.clear();
        } else if (inFence) {
            line.clear();
        }
    }
    return lines;
}

// Inline code spans (`…`, ``…``) blanked out: what they contain is not markdown.
std::string withoutCodeSpans(const std::string& line) {
    std::string out = line;
    std::size_t i = 0;
    while (i < out.size()) {
        if (out[i] != '`') {
            ++i;
            continue;
        }
        std::size_t run = 0;
        while (i + run < out.size() && out[i + run] == '`') ++run;
        const std::string fence(run, '`');
        std::size_t close = out.find(fence, i + run);
        while (close != std::string::npos && close + run < out.size() && out[close + run] == '`')
            close = out.find(fence, close + run + 1);
        if (close == std::string::npos) {
            i += run;
            continue;
        }
        for (std::size_t k = i + run; k < close; ++k) out[k] = ' ';
        i = close + run;
    }
    return out;
}

// GitHub's anchor for a heading: the rendered text in lower case, every character but letters,
// digits, spaces, '-' and '_' dropped, spaces turned into '-'. Non-ASCII: symbols and punctuation
// (Latin-1 signs, ×, ÷, general punctuation such as — and …, arrows, mathematical operators,
// superscripts) are dropped, letters kept.
std::string githubSlug(std::string heading) {
    heading = std::regex_replace(heading, std::regex(R"(!?\[([^\]]*)\]\([^)]*\))"), "$1");  // links → their text
    std::string slug;
    for (std::size_t i = 0; i < heading.size();) {
        const unsigned char c = static_cast<unsigned char>(heading[i]);
        if (c < 0x80) {
            if (std::isalnum(c) || c == '-' || c == '_') slug += char(std::tolower(c));
            else if (c == ' ') slug += '-';
            ++i;
            continue;
        }
        // Decode one UTF-8 sequence.
        const std::size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
        unsigned codePoint = length == 1 ? c : length == 2 ? (c & 0x1F) : length == 3 ? (c & 0x0F) : (c & 0x07);
        for (std::size_t k = 1; k < length && i + k < heading.size(); ++k)
            codePoint = (codePoint << 6) | (static_cast<unsigned char>(heading[i + k]) & 0x3F);
        const bool symbol = (codePoint >= 0x80 && codePoint <= 0xBF) || codePoint == 0xD7 || codePoint == 0xF7 ||
                            (codePoint >= 0x2000 && codePoint <= 0x2BFF) || (codePoint >= 0x3000 && codePoint <= 0x303F);
        if (!symbol) slug += heading.substr(i, length);
        i += length;
    }
    return slug;
}

// Every anchor a markdown file offers: one per ATX heading (# … ######), duplicates numbered
// -1, -2, … as GitHub does.
std::set<std::string> anchorsOf(const fs::path& file) {
    static const std::regex heading(R"(^ {0,3}#{1,6}[ \t]+(.*?)[ \t]*#*[ \t]*$)");
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    for (const std::string& line : linesOutsideCode(readText(file))) {
        std::smatch m;
        if (!std::regex_match(line, m, heading)) continue;
        const std::string slug = githubSlug(m[1].str());
        const int n = seen[slug]++;
        anchors.insert(n == 0 ? slug : slug + "-" + std::to_string(n));
    }
    return anchors;
}

struct Link {
    fs::path file;
    int line = 0;
    std::string target;
};

// Inline links and images [text](target "title"), <autolinks> aside, and reference definitions
// [label]: target, outside code.
std::vector<Link> linksOf(const fs::path& file) {
    static const std::regex inlineLink(R"(\[[^\]]*\]\(\s*<?([^)\s>]*)>?(?:\s+"[^"]*")?\s*\))");
    static const std::regex definition(R"(^ {0,3}\[[^\]]+\]:\s*<?([^\s>]+)>?)");
    std::vector<Link> links;
    const std::vector<std::string> lines = linesOutsideCode(readText(file));
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string line = withoutCodeSpans(lines[i]);
        for (std::sregex_iterator it(line.begin(), line.end(), inlineLink), end; it != end; ++it)
            links.push_back({file, int(i) + 1, (*it)[1].str()});
        std::smatch m;
        if (std::regex_search(line, m, definition)) links.push_back({file, int(i) + 1, m[1].str()});
    }
    return links;
}

std::string percentDecoded(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
            out += char(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

std::vector<fs::path> markdownFiles() {
    std::vector<fs::path> files = {kRoot / "README.md"};
    if (fs::is_directory(kRoot / "docs"))
        for (const auto& entry : fs::directory_iterator(kRoot / "docs"))
            if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string repoPath(const fs::path& path) { return path.lexically_relative(kRoot).generic_string(); }

// ---- docs/timings.md ----------------------------------------------------------------------

std::vector<std::string> tableCells(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    bool escaped = false;
    for (std::size_t i = 1; i < line.size(); ++i) {  // line[0] is the leading '|'
        const char c = line[i];
        if (c == '|' && !escaped) {
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += c;
        }
        escaped = c == '\\';
    }
    if (cell.find_first_not_of(" \t") != std::string::npos) cells.push_back(cell);  // no closing '|'
    for (std::string& c : cells) {
        const std::size_t a = c.find_first_not_of(" \t"), b = c.find_last_not_of(" \t");
        c = a == std::string::npos ? "" : c.substr(a, b - a + 1);
    }
    return cells;
}

// The key paths and types documented in docs/timings.md: every table whose header's first two
// cells are "key" and "type"; each row names one key path in backticks (`a.b`, `list[].c`).
std::map<std::string, std::string> documentedKeys(std::vector<std::string>& problems) {
    std::map<std::string, std::string> keys;
    const std::vector<std::string> lines = linesOutsideCode(readText(kRoot / "docs" / "timings.md"));
    static const std::regex keyCell(R"(^`([A-Za-z0-9_]+(?:\[\])?(?:\.[A-Za-z0-9_]+(?:\[\])?)*)`$)");
    bool inKeyTable = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line.empty() || line[0] != '|') {
            inKeyTable = false;
            continue;
        }
        const std::vector<std::string> cells = tableCells(line);
        if (!inKeyTable) {
            inKeyTable = cells.size() >= 2 && cells[0] == "key" && cells[1] == "type";
            ++i;  // the |---| row
            continue;
        }
        std::smatch m;
        if (cells.size() < 2 || !std::regex_match(cells[0], m, keyCell)) {
            problems.push_back("docs/timings.md:" + std::to_string(i + 1) +
                               ": a key table row must start with a key path in backticks: " + line);
            continue;
        }
        std::string type = cells[1];
        type.erase(std::remove(type.begin(), type.end(), '`'), type.end());
        if (keys.count(m[1].str()))
            problems.push_back("docs/timings.md:" + std::to_string(i + 1) + ": " + m[1].str() + " documented twice");
        keys[m[1].str()] = type;
    }
    return keys;
}

std::string typeOf(const nlohmann::json& value) {
    if (value.is_string()) return "string";
    if (value.is_boolean()) return "boolean";
    if (value.is_number_integer()) return "integer";
    if (value.is_number()) return "number";
    if (value.is_object()) return "object";
    if (value.is_array()) {
        bool objects = !value.empty(), integers = true;
        for (const auto& element : value) {
            objects = objects && element.is_object();
            integers = integers && element.is_number_integer();
        }
        if (objects) return "array of objects";
        if (integers) return "array of integers";  // also an empty array
        return "array";
    }
    return "null";
}

// Does a value of `actual` type satisfy the documented type? (An integer is also a number; an
// empty array, written as an array of integers, also an empty array of objects.)
bool satisfies(const std::string& actual, const std::string& documented) {
    return actual == documented || (actual == "integer" && documented == "number");
}

// Every key path in `value`: objects add ".key", arrays of objects add "[]" before their keys.
void collectKeys(const nlohmann::json& value, const std::string& path, std::map<std::string, std::set<std::string>>& keys) {
    if (value.is_object()) {
        for (const auto& [key, child] : value.items()) {
            const std::string childPath = path.empty() ? key : path + "." + key;
            keys[childPath].insert(typeOf(child));
            collectKeys(child, childPath, keys);
        }
    } else if (value.is_array()) {
        for (const auto& element : value)
            if (element.is_object() || element.is_array()) collectKeys(element, path + "[]", keys);
    }
}

std::map<std::string, std::set<std::string>> writtenKeys(const std::string& extraArguments, const fs::path& dir,
                                                         const std::string& name) {
    const fs::path json = dir / (name + ".json");
    const auto result = vct::test::runVct("render -q --scene cornell --width 32 --height 24 --voxel-levels 5 "
                                          "--light-view-res 256 " + extraArguments + " --timings " + json.string() +
                                          " --out " + (dir / (name + ".png")).string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    std::map<std::string, std::set<std::string>> keys;
    if (result.exitCode != 0) return keys;
    collectKeys(nlohmann::json::parse(readText(json)), "", keys);
    return keys;
}

}  // namespace

TEST(Docs, EveryRelativeLinkResolves) {
    std::vector<std::string> broken;
    std::size_t checked = 0;
    std::map<fs::path, std::set<std::string>> anchorCache;
    for (const fs::path& file : markdownFiles()) {
        for (const Link& link : linksOf(file)) {
            std::string target = link.target;
            const std::string where = repoPath(link.file) + ":" + std::to_string(link.line) + ": (" + target + ") ";
            if (std::regex_search(target, std::regex(R"(^[A-Za-z][A-Za-z0-9+.-]*:)"))) continue;  // http:, mailto:, …
            std::string fragment;
            if (const std::size_t hash = target.find('#'); hash != std::string::npos) {
                fragment = target.substr(hash + 1);
                target = target.substr(0, hash);
            }
            ++checked;
            fs::path resolved = target.empty() ? link.file
                                : target[0] == '/' ? kRoot / percentDecoded(target.substr(1))
                                                   : link.file.parent_path() / percentDecoded(target);
            resolved = resolved.lexically_normal();
            const std::string inside = resolved.lexically_relative(kRoot).generic_string();
            if (inside.empty() || inside.rfind("..", 0) == 0) {
                broken.push_back(where + "points outside the repository");
                continue;
            }
            if (!fs::exists(resolved)) {
                broken.push_back(where + "no such file: " + inside);
                continue;
            }
            if (fragment.empty() || resolved.extension() != ".md") continue;
            if (!anchorCache.count(resolved)) anchorCache[resolved] = anchorsOf(resolved);
            if (!anchorCache[resolved].count(percentDecoded(fragment)))
                broken.push_back(where + "no heading with the anchor #" + fragment + " in " + inside);
        }
    }
    EXPECT_GT(checked, 20u) << "the link parser found almost no links: is it still working?";
    std::string message;
    for (const std::string& b : broken) message += "  " + b + "\n";
    EXPECT_TRUE(broken.empty()) << broken.size() << " broken link(s):\n" << message;
}

TEST(Docs, SlugsFollowGitHub) {
    EXPECT_EQ(githubSlug("The `vct` command"), "the-vct-command");
    EXPECT_EQ(githubSlug("Reference renderer and error metrics"), "reference-renderer-and-error-metrics");
    EXPECT_EQ(githubSlug("Status / known limits"), "status--known-limits");
    EXPECT_EQ(githubSlug("voxels.bytes (object)"), "voxelsbytes-object");
    EXPECT_EQ(githubSlug("Frame graph: skip what the scene doesn't need"), "frame-graph-skip-what-the-scene-doesnt-need");
    EXPECT_EQ(githubSlug("3³ bricks — filtering"), "3-bricks--filtering");
    EXPECT_EQ(githubSlug("snake_case and-dash"), "snake_case-and-dash");
}

TEST(Docs, ReadmeIsShort) {
    const std::size_t lines = splitLines(readText(kRoot / "README.md")).size();
    EXPECT_GT(lines, 0u);
    EXPECT_LE(lines, 200u) << "README.md is a page a newcomer reads in two minutes; details belong in docs/";
}

TEST(Docs, TimingsSchemaMatchesWhatRenderWrites) {
    std::vector<std::string> problems;
    const std::map<std::string, std::string> documented = documentedKeys(problems);
    EXPECT_TRUE(problems.empty()) << [&] {
        std::string s;
        for (const auto& p : problems) s += "  " + p + "\n";
        return s;
    }();
    ASSERT_GT(documented.size(), 10u) << "no key tables (| key | type | meaning |) found in docs/timings.md";

    const auto dir = vct::test::testDir();
    const auto written = writtenKeys("", dir, "gi_on");
    ASSERT_FALSE(written.empty());

    std::string undocumented, notWritten, wrongType;
    for (const auto& [key, types] : written) {
        const auto doc = documented.find(key);
        if (doc == documented.end()) {
            undocumented += "  " + key + " (" + *types.begin() + ")\n";
            continue;
        }
        for (const std::string& type : types)
            if (!satisfies(type, doc->second))
                wrongType += "  " + key + ": documented " + doc->second + ", written " + type + "\n";
    }
    for (const auto& [key, type] : documented)
        if (!written.count(key)) notWritten += "  " + key + "\n";
    EXPECT_TRUE(undocumented.empty()) << "written by vct render --timings but not in docs/timings.md:\n" << undocumented;
    EXPECT_TRUE(notWritten.empty()) << "in docs/timings.md but not written by vct render --timings:\n" << notWritten;
    EXPECT_TRUE(wrongType.empty()) << "types that disagree:\n" << wrongType;

    // As documented, `voxels` is there only when the renderer built the octree: not with GI off.
    const auto withoutGi = writtenKeys("--gi off", dir, "gi_off");
    std::string unexpected, missing;
    for (const auto& [key, types] : withoutGi)
        if (key.rfind("voxels", 0) == 0) unexpected += "  " + key + "\n";
    for (const auto& [key, type] : documented)
        if (key.rfind("voxels", 0) != 0 && !withoutGi.count(key)) missing += "  " + key + "\n";
    EXPECT_TRUE(unexpected.empty()) << "with --gi off no octree is built, yet the JSON has:\n" << unexpected;
    EXPECT_TRUE(missing.empty()) << "with --gi off these documented keys are missing:\n" << missing;
}

namespace {

// A pass's row of docs/frame.md's table, made from the pass table itself.
std::string passRow(const vct::PassDeclaration& pass) {
    auto inputs = [](vct::InputSet set) {
        std::string text;
        set.forEach([&](vct::Input i) { text += (text.empty() ? "" : ", ") + std::string(vct::inputName(i)); });
        return text;
    };
    auto resources = [](vct::ResourceSet set) {
        std::string text;
        set.forEach([&](vct::Resource r) { text += (text.empty() ? "" : ", ") + std::string(vct::resourceName(r)); });
        return text;
    };
    return std::string("| `") + pass.name + "` | " + vct::stageName(pass.stage) + " | " + inputs(pass.inputs) + " | " +
           resources(pass.reads) + " | " + resources(pass.writes) + " | " + pass.shaders + " |";
}

}  // namespace

TEST(Docs, FramePassTableMatchesTheCode) {
    // docs/frame.md shows the pass table row by row; a pass added, removed or re-declared in
    // engine/pipeline/frame_passes.cpp without the docs following fails here.
    const std::vector<std::string> lines = splitLines(readText(kRoot / "docs" / "frame.md"));
    std::vector<std::string> documented;
    for (const std::string& line : lines)
        if (line.rfind("| `", 0) == 0 && line.find("` |") != std::string::npos) {
            const std::string name = line.substr(3, line.find('`', 3) - 3);
            for (const vct::PassDeclaration& pass : vct::framePasses())
                if (name == pass.name) documented.push_back(line);
        }
    std::string expected;
    std::vector<std::string> expectedRows;
    for (const vct::PassDeclaration& pass : vct::framePasses()) {
        expectedRows.push_back(passRow(pass));
        expected += expectedRows.back() + "\n";
    }
    EXPECT_EQ(documented, expectedRows) << "docs/frame.md's pass table should read:\n" << expected;
}
