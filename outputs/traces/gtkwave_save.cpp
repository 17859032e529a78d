#include "outputs/traces/gtkwave_save.hpp"

#include <fmt/format.h>

namespace parsons::cli {

std::string gtkwave_signal_name(const VcdVariable& v) {
    std::string name = v.scope + "." + v.reference;
    if (v.kind == "wire" && v.width > 1) {
        name += fmt::format("[{}:0]", v.width - 1);
    }
    return name;
}

namespace {

// Lines under one "@HEX" share its flags: a new one only where they change.
class SaveLines {
public:
    void flags(std::uint64_t f) {
        if (!any_ || f != flags_) {
            text_ += fmt::format("@{:x}\n", f);
            flags_ = f;
            any_ = true;
        }
    }
    void line(std::string_view s) {
        text_ += s;
        text_ += '\n';
    }
    std::string take() { return std::move(text_); }

private:
    std::string text_;
    std::uint64_t flags_ = 0;
    bool any_ = false;
};

} // namespace

std::string gtkwave_save_file(const std::vector<VcdVariable>& declared, std::string_view dumpfile,
                              std::string_view savefile) {
    namespace flag = gtkwave_flag;
    SaveLines out;
    out.line("[*] GTKWave save file written by parsons beside its trace (docs/output-formats.md):");
    out.line("[*] one group per scope, each axis's real position (inches) as an analogue wave");
    out.line(fmt::format("[dumpfile] \"{}\"", dumpfile));
    out.line(fmt::format("[savefile] \"{}\"", savefile));
    out.line("[timestart] 0");
    out.line("[sst_expanded] 1");
    out.line("[signals_width] 330");
    // The scopes in the order the VCD declared them; each a group of its variables.
    std::vector<std::string> scopes;
    for (const VcdVariable& v : declared) {
        if (scopes.empty() || scopes.back() != v.scope) {
            scopes.push_back(v.scope);
        }
    }
    for (const std::string& scope : scopes) {
        out.flags(flag::kBegin);
        out.line("-" + scope);
        for (const VcdVariable& v : declared) {
            if (v.scope != scope) {
                continue;
            }
            if (v.kind == "real") {
                out.flags(flag::kPosition);
                out.line(gtkwave_signal_name(v));
                out.flags(flag::kTaller);
                for (int i = 0; i < kGtkwavePositionStretch; ++i) {
                    out.line("-");
                }
                continue;
            }
            out.flags(v.width > 1 ? flag::kSwitch : flag::kWire);
            out.line(gtkwave_signal_name(v));
        }
        out.flags(flag::kEnd);
        out.line("-" + scope);
    }
    return out.take();
}

} // namespace parsons::cli
