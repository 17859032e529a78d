// The job descriptions a run reads (cli/support/job_files.hpp).
#include "cli/support/job_files.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

namespace parsons::cli {

using cardreader::DeckError;

decks::JobDescription read_job(const std::string& file, const std::string& deck_path,
                               const DeckFlags& deck_flags) {
    const std::string text =
        read_text_file(file, "cannot open the job description (written by 'parsons gen airfoil' "
                             "beside the deck; or give --job FILE)");
    decks::JobDescription job;
    try {
        job = decks::job_from_json(text);
    } catch (const decks::JobError& e) {
        throw DeckError::in_file(file, e.what());
    }
    if (!job.deck_fingerprint.empty() && deck_path != "-") {
        const cardreader::DeckFingerprint fingerprint = fingerprint_deck(deck_path, deck_flags);
        if (fingerprint.hex() != job.deck_fingerprint) {
            throw DeckError::in_file(
                file, fmt::format("this job description was written for another deck ({} cards, "
                                  "fingerprint {}), not {} ({} cards, fingerprint {}): give the "
                                  "job the deck was generated with (--job FILE)",
                                  job.deck_cards, job.deck_fingerprint, deck_path,
                                  fingerprint.cards(), fingerprint.hex()));
        }
    }
    return job;
}

decks::PressFeederJob read_press_job(const std::string& file) {
    const std::string text = read_text_file(
        file, "cannot open the press-feeder job (written by 'parsons gen press-feeder' beside "
              "the deck as DECK.job.json)");
    try {
        return decks::press_job_from_json(text);
    } catch (const decks::JobError& e) {
        throw DeckError::in_file(file, e.what());
    }
}

decks::TappingJob read_tapping_job(const std::string& file) {
    const std::string text = read_text_file(
        file, "cannot open the tapping job (written by 'parsons gen tapping' beside the deck as "
              "DECK.job.json)");
    try {
        return decks::tapping_job_from_json(text);
    } catch (const decks::JobError& e) {
        throw DeckError::in_file(file, e.what());
    }
}

} // namespace parsons::cli
