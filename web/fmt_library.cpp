// fmt, compiled once for the WebAssembly build (cmake/wasm.cmake). Debian's libfmt-dev has the
// headers and a native library only; compiled header-only (FMT_HEADER_ONLY), fmt's implementation
// was compiled again in each of the hundred files that format, some 2 s each. Here it is
// compiled in this one file: format-inl.h defines the library's functions, and the templates
// that format.h declares `extern template` are instantiated below, for the characters it names.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {
template FMT_API auto thousands_sep_impl<char>(locale_ref) -> thousands_sep_result<char>;
template FMT_API auto thousands_sep_impl<wchar_t>(locale_ref) -> thousands_sep_result<wchar_t>;
template FMT_API auto decimal_point_impl(locale_ref) -> char;
template FMT_API auto decimal_point_impl(locale_ref) -> wchar_t;
} // namespace detail
FMT_END_NAMESPACE
