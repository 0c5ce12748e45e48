// SPDX-License-Identifier: MIT
#include "rvimage/rvimage.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "core/error.h"
#include "core/quote.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/png.h"
#include "program/arguments.h"
#include "program/shell.h"

namespace rt {
namespace {

constexpr const char* kProgram = "rvimage";

bool EndsWith(const std::string& s, std::string_view suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(), [](char lower, char c) {
               return std::tolower(static_cast<unsigned char>(c)) == lower;
           });
}

/// The output's kind by its name; a user error for any other name.
OutputKind KindOf(const std::string& path) {
    if (EndsWith(path, ".exr")) return OutputKind::Exr;
    if (EndsWith(path, ".hdr") || EndsWith(path, ".pic")) return OutputKind::Hdr;
    if (EndsWith(path, ".png")) return OutputKind::Png;
    ThrowUserError("output '" + path + "' must end in .exr, .hdr, .pic or .png");
}

int PositiveInt(const std::string& option, const std::string& word) {
    if (!IsIntArgument(word)) ThrowUserError("bad value '" + word + "' for " + option);
    const long v = std::strtol(word.c_str(), nullptr, 10);
    if (v <= 0 || v > 1 << 20) ThrowUserError("bad value '" + word + "' for " + option);
    return static_cast<int>(v);
}

double RealValue(const std::string& option, const std::string& word) {
    if (!IsRealArgument(word)) ThrowUserError("bad value '" + word + "' for " + option);
    return std::strtod(word.c_str(), nullptr);
}

void ParseLayers(const std::string& list, PictureSettings& s) {
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t comma = list.find(',', start);
        if (comma == std::string::npos) comma = list.size();
        const std::string name = list.substr(start, comma - start);
        if (name == "indirect") {
            s.indirectLayer = true;
        } else if (name == "records") {
            s.recordsLayer = true;
        } else if (name == "outcome") {
            s.outcomeLayer = true;
        } else if (name == "all") {
            s.indirectLayer = s.recordsLayer = s.outcomeLayer = true;
        } else {
            ThrowUserError("unknown layer '" + name + "' (indirect, records, outcome, all)");
        }
        start = comma + 1;
    }
}

/// SplitMix64: a pixel's jitter depends only on -seed and the pixel, so

/// Progress on stderr: a carriage-return-updated bar on a terminal once the
/// render has run a second; with -t N a plain line every N seconds where no
/// bar is drawn.
class Progress {
public:
    Progress(std::ostream& err, std::ostream& msg, bool terminal, int reportSeconds)
        : err_(err), msg_(msg), terminal_(terminal), reportSeconds_(reportSeconds),
          start_(Clock::now()), nextReport_(start_ + std::chrono::seconds(reportSeconds)) {}

    double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    void Update(std::size_t done, std::size_t total) {
        const auto now = Clock::now();
        const double elapsed = Seconds();
        const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
        if (terminal_ && elapsed >= 1.0 && (now - lastDraw_ >= std::chrono::milliseconds(100))) {
            Draw(fraction, elapsed);
            lastDraw_ = now;
        }
        if (reportSeconds_ > 0 && !shown_ && now >= nextReport_) {
            char line[96];
            std::snprintf(line, sizeof line, "%s: %.1f%% done after %.1f s\n", kProgram,
                          100.0 * fraction, elapsed);
            msg_ << line;
            msg_.flush();
            nextReport_ = now + std::chrono::seconds(reportSeconds_);
        }
    }

    /// Completes the bar (100 %, a newline) if one was drawn.
    void Finish() {
        if (shown_) {
            Draw(1.0, Seconds());
            err_ << '\n';
            err_.flush();
        }
    }

private:
    using Clock = std::chrono::steady_clock;

    void Draw(double fraction, double elapsed) {
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(static_cast<std::size_t>(kWidth), '.');
        std::fill(bar.begin(), bar.begin() + std::clamp(filled, 0, kWidth), '#');
        char line[160];
        std::snprintf(line, sizeof line, "\r%s: [%s] %3d%%  %.1f s", kProgram, bar.c_str(),
                      static_cast<int>(100.0 * fraction), elapsed);
        err_ << line;
        err_.flush();
        shown_ = true;
    }

    std::ostream& err_;
    std::ostream& msg_;
    bool terminal_;
    int reportSeconds_;
    Clock::time_point start_;
    Clock::time_point nextReport_;
    Clock::time_point lastDraw_{};
    bool shown_ = false;
};

}  // namespace

RvimageCommandLine ParseRvimageCommandLine(std::span<const std::string> args,
                                           const WarningSink& warn) {
    if (args.empty()) ThrowUserError("no arguments");
    std::vector<std::string> words(args.begin(), args.end());
    for (std::size_t i = 1; i < words.size(); ++i) ExpandInPlace(words, i);
    RvimageCommandLine cl;
    cl.args = words;
    cl.args[0] = ProgramName(words[0]);
    PictureSettings& s = cl.settings;
    std::vector<std::string> rest{words[0]};
    const std::size_t n = words.size();
    for (std::size_t i = 1; i < n; ++i) {
        const std::string& a = words[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= n) ThrowUserError("missing value for " + a);
            return words[++i];
        };
        if (a.size() >= 3 && a[0] == '-' && a[1] == 'v') {
            const std::optional<int> used =
                ParseViewOption(s.view, std::span<const std::string>(words).subspan(i));
            if (used) {
                i += static_cast<std::size_t>(*used);
                continue;
            }
        }
        if (a == "-x") {
            s.xResolution = PositiveInt(a, value());
        } else if (a == "-y") {
            s.yResolution = PositiveInt(a, value());
        } else if (a == "-pa") {
            s.pixelAspect = RealValue(a, value());
            if (s.pixelAspect < 0) ThrowUserError("bad value for -pa");
        } else if (a == "-pj") {
            s.jitter = RealValue(a, value());
            if (s.jitter < 0 || s.jitter > 1) ThrowUserError("-pj must be between 0 and 1");
        } else if (a == "-o") {
            s.outputPath = value();
        } else if (a == "-rscale") {
            s.recordScale = RealValue(a, value());
            if (s.recordScale < 0) ThrowUserError("-rscale must not be negative");
        } else if (a == "-layers") {
            ParseLayers(value(), s);
        } else {
            rest.push_back(a);
        }
    }
    cl.rtrace = ParseCommandLine(rest, warn);
    if (cl.rtrace.action != CommandLine::Action::Render) return cl;
    if (s.outputPath.empty()) ThrowUserError("no output picture (-o out.exr, .hdr or .png)");
    static_cast<void>(KindOf(s.outputPath));  // refused here, before the error file opens
    if (cl.rtrace.options.outputSpec != "v" && warn)
        warn("-o" + cl.rtrace.options.outputSpec + " ignored: the picture holds values (-ov)");
    return cl;
}

PicturePlan PlanPicture(const PictureSettings& s) {
    PicturePlan plan;
    plan.kind = KindOf(s.outputPath);
    try {
        plan.view = SetupView(s.view);
    } catch (const Error& e) {
        ThrowUserError(std::string("bad view: ") + e.what());
    }
    plan.width = s.xResolution;
    plan.height = s.yResolution;
    double aspect = s.pixelAspect;
    NormalizeAspect(ViewAspect(plan.view), aspect, plan.width, plan.height);
    if (plan.width <= 0 || plan.height <= 0) ThrowUserError("picture resolution too small");
    return plan;
}

int RunRvimage(std::span<const std::string> args, std::ostream& out, std::ostream& err,
               const RunEnvironment& env, bool errIsTerminal) {
    ProgramShell shell(kProgram, err);
    const WarningSink& warn = shell.Warn();
    return shell.Run([&] {
        RvimageCommandLine cl = ParseRvimageCommandLine(args, warn);
        const RtraceOptions& opt = cl.rtrace.options;
        shell.SetWarnings(opt.warnings);
        if (const std::optional<std::string> text = InfoText(cl.rtrace)) {
            out << *text;
            return 0;
        }
        if (!shell.OpenErrorFile(opt.errorFile, env.pid, cl.args)) return 2;
        const PictureSettings& s = cl.settings;
        const PicturePlan plan = PlanPicture(s);
        const PreparedView& view = plan.view;
        const int width = plan.width, height = plan.height;
        const OutputKind kind = plan.kind;
        if (kind == OutputKind::Hdr && (s.indirectLayer || s.outcomeLayer || s.recordsLayer))
            warn("layers are written only to OpenEXR (.exr) or, for records, PNG");

        if (!env.makeEvaluator) throw Error(Error::Kind::Internal, "no renderer configured");
        std::unique_ptr<RayEvaluator> evaluator = env.makeEvaluator(cl.rtrace.sceneFiles, opt, warn);
        Progress progress(err, shell.Messages(), errIsTerminal, opt.reportSeconds);
        const std::size_t batch = 1024 * static_cast<std::size_t>(std::max(1, opt.processes));
        const Image image = RenderView(
            *evaluator, view, width, height, s, static_cast<unsigned>(opt.seed),
            opt.ambient.accuracy, batch,
            [&](std::size_t done, std::size_t total) { progress.Update(done, total); }, warn);
        evaluator->Finish();
        progress.Finish();

        const std::string commandLine = QuoteWords(args);
        std::string viewText = FormatView(s.view);
        if (!viewText.empty() && viewText.front() == ' ') viewText.erase(0, 1);
        switch (kind) {
            case OutputKind::Exr:
                WriteExr(s.outputPath, image,
                         {{"commandLine", commandLine},
                          {"software", std::string(kLazyradVersion)},
                          {"view", viewText}});
                break;
            case OutputKind::Hdr:
                WriteHdr(s.outputPath, image,
                         {commandLine, "SOFTWARE= " + std::string(kLazyradVersion),
                          "VIEW= " + viewText});
                break;
            case OutputKind::Png: {
                const double exposure = AutoExposure(image);
                WritePng(s.outputPath, image, exposure);
                if (s.recordsLayer) {
                    std::string path = s.outputPath.substr(0, s.outputPath.size() - 4);
                    WritePng(path + "_records.png", RecordsPicture(image, exposure), 1.0);
                }
                break;
            }
        }
        if (opt.reportSeconds > 0) {
            const std::string summary = evaluator->Summary();
            char tail[96];
            std::snprintf(tail, sizeof tail, "%s%dx%d pixels in %.2f s", summary.empty() ? "" : ", ",
                          width, height, progress.Seconds());
            shell.Say(summary + tail);
        }
        return 0;
    });
}

}  // namespace rt
