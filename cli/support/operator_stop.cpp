#include "cli/support/operator_stop.hpp"

#include "outputs/output_file.hpp"

namespace parsons::cli {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_operator_signal(int signal) {
    g_signal = signal;
}

} // namespace

OperatorStop::OperatorStop() {
    g_signal = 0;
    give_up_on_signal(&g_signal);
    stop_on_broken_pipe(&g_signal);
    struct sigaction action {};
    action.sa_handler = on_operator_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
}

const volatile std::sig_atomic_t* OperatorStop::flag() const {
    return &g_signal;
}

int OperatorStop::signal() const {
    return g_signal;
}

ExitCode OperatorStop::interrupted_exit() const {
    return g_signal == SIGTERM ? ExitCode::terminated : ExitCode::interrupted;
}

void OperatorStop::restore() {
    if (!restored_) {
        give_up_on_signal(nullptr);
        stop_on_broken_pipe(nullptr);
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
        restored_ = true;
    }
}

} // namespace parsons::cli
