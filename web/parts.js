// The cabinet's parts as the exhibit page and the --html replay explain them (web/viewer.js,
// web/tour.js): by patent numeral, what the part does in plain words, and the passage of
// US 2,820,187 that describes it with the figure it is drawn in. The passages are the patent's
// own words (../shared/seeds, the Parsons patent), cut at sentence ends; docs/patent-map.md
// maps the same numerals to the code.
"use strict";

const ParsonsParts = {
  // What each part does, by its patent numeral (docs/patent-map.md).
  LEGEND: {
    "104": "Absolute counter, inches digit: a ten-position stepping switch stepped by the inch impulses of commutator 96. With 106, 108 and 110 it reads where the part is, through the instrument shaft.",
    "106": "Absolute counter, tenths digit: stepped by commutator 98; carries into 104.",
    "108": "Absolute counter, hundredths digit: stepped by commutator 100; carries into 106.",
    "110": "Absolute counter, thousandths digit: stepped once for every 0.001 inch impulse of commutator 102.",
    "310": "Increment counter (112), thousandths digit: one step per impulse of commutator 102; carries into 312 over channel 333.",
    "312": "Increment counter (112), hundredths digit; carries into 314.",
    "314": "Increment counter (112), tenths digit; carries into 316.",
    "316": "Increment counter (112), inches digit: counts the impulses of this move from the last stop; at the stop it must stand on the stored check number (incremental comparer 122″).",
    "350": "Absolute storage, inches digit: ten holding relays. The brushes close the relay of the inches digit of each number punched for the axis, the first and second slow-down points and the stop, so up to three relays hold at once (design rule 2); they hold for the whole move.",
    "352": "Absolute storage, tenths digit: the relays of the tenths digits of the slow-down points and the stop (the patent's example closes relays 7, 8 and 9 for 8.785, 8.885 and 8.985).",
    "354": "Absolute storage, hundredths digit: the relays of the hundredths digits of the slow-down points and the stop.",
    "356": "Absolute storage, thousandths digit: the relays of the thousandths digits of the slow-down points and the stop.",
    "318": "Incremental storage, thousandths digit: this bank holds the digit of this position of the card's check number: the length of the move from the last stop, which the increment counter 112 must reach together with the stop (one relay per bank; the patent's example 0.485 closes relay 0 of 324, 4 of 322, 8 of 320 and 5 of 318).",
    "320": "Incremental storage, hundredths digit: this bank holds the digit of this position of the card's check number: the length of the move from the last stop, which the increment counter 112 must reach together with the stop (one relay per bank; the patent's example 0.485 closes relay 0 of 324, 4 of 322, 8 of 320 and 5 of 318).",
    "322": "Incremental storage, tenths digit: this bank holds the digit of this position of the card's check number: the length of the move from the last stop, which the increment counter 112 must reach together with the stop (one relay per bank; the patent's example 0.485 closes relay 0 of 324, 4 of 322, 8 of 320 and 5 of 318).",
    "324": "Incremental storage, inches digit: ten holding relays the brushes close from the card's \"Check\" column; this bank holds the digit of this position of the card's check number: the length of the move from the last stop, which the increment counter 112 must reach together with the stop (one relay per bank; the patent's example 0.485 closes relay 0 of 324, 4 of 322, 8 of 320 and 5 of 318).",
    "122'": "Absolute comparer (122′): conducts whenever the absolute counters stand on digits held in the absolute storage: at the first slow-down point, the second, and the stop (design rule 2). Each closing steps speed switch 236 through stepping relay 256.",
    "122''": "Incremental comparer (122″): conducts when the increment counter (310–316) stands on the check number held in banks 318–324: at the stop it tells that the move was as long as the card says (lamp 272).",
    "236": "Speed switch: the card sets the start speed; it steps once per impulse of stepping relay 256 toward off (0), each step a slower motor speed.",
    "238": "The speed switch's off contact: closed when 236 stands on off and the axis is stopped.",
    "256": "Stepping relay: each impulse from a comparer steps speed switch 236 one position.",
    "257": "The channel from the comparers to stepping relay 256.",
    "258": "Delay device: a timed hold in channel 260 so the speed switch does not step twice on one comparer closing.",
    "270": "Lamp: the absolute comparer conducting while 236 stands on off. Lit at every stop; the operator checks it against 272.",
    "272": "Lamp: the incremental comparer conducting while 236 stands on off. Lit at every stop.",
    "268": "Indicator: lights when the check at a stop finds the position wrong (the balancing circuit unbalanced) and the machine stops.",
    "204": "Master switch: the cabinet's power to the motors. The electromagnet opens it when a check fails: the machine stops.",
    "265": "Electromagnet: opens master switch 204 when balancing circuit 266 is unbalanced.",
    "266": "Balancing circuit: compares the counters with the check field of the card at every stop (1 = unbalanced).",
    "280": "Stepping shaft: steps through the card's sequence pattern, starting the axes whose pattern marks its position.",
    "278": "The stepping shaft's motor.",
    "274": "The impulse channel to stepping shaft 280's motor.",
    "276": "The circuit to motor 278.",
    "284": "Unit counting simultaneous impulses: the shaft steps only when every axis of this step has stopped.",
    "288": "Single-impulse device: breaks circuit 276 after it has delivered its impulse, until channel 302.",
    "290": "Zeroizing contact: at the end of a card, clears the storages for the next.",
    "292": "Zeroizing circuit.",
    "294": "Channel clearing the absolute storage.",
    "298": "Channel clearing the incremental storage and counter.",
    "300": "Channel opening the sequence contacts.",
    "302": "Channel actuating device 288 to close circuit 274 again.",
    "304": "Channel indexing the card reader to the next card.",
    "134": "Card reader: its brushes sense the holes of one card and pick the storage relays; then the card is checked and the axes start in their sequence.",
    "165": "Spindle control (column 1 of the card): 0 off, 1 forward, 2 reverse.",
    "214": "Reversing control: the direction the motor drives the lead screw (the card's motion sign).",
    "224": "Sequence switch: its contacts 226–234 say in which step of shaft 280 this axis moves.",
    "226": "Sequence contact: this axis moves in step 1 of the stepping shaft.",
    "228": "Sequence contact: step 2.",
    "230": "Sequence contact: step 3.",
    "232": "Sequence contact: step 4.",
    "234": "Sequence contact: step 5.",
    "96": "Commutator 96 (inches): two contact sets, each changes over at every impulse it sends; a missed impulse shows as the two disagreeing.",
    "98": "Commutator 98 (tenths).",
    "100": "Commutator 100 (hundredths).",
    "102": "Commutator 102 (thousandths): an impulse every 0.001 inch of the instrument shaft.",
    "38": "Motor of the table lead screw.",
    "50": "Motor of the cross-slide screw.",
    "46": "Motor of the vertical screws.",
    "44": "Motor of the fixture's transverse screw (swivel).",
    "40": "Motor of the sine-plate screws (tilt).",
  },

  // Numeral -> [figure, passage]. A part without an entry of its own is drawn in Fig. 10, the
  // circuits of the control cabinet.
  PASSAGES: {
    "134": ["Figs. 8, 10", "When a card 162 is fed into the card reader 134, the first bank of brushes therein detects the information punched into the card for controlling the direction of rotation of the cutter spindle."],
    "350": ["Fig. 12", "If, as an example, the \"first slow down\" number is 8.785, the \"second slow down\" number is 8.885, and the \"stop\" number is 8.985, then an impulse over channel 358 will cause the relay No. 8 in the bank 350 to close. An impulse over channel 360 will cause relays Nos. 7, 8 and 9 in bank 352 to close, an impulse over channel 362 will cause relay No. 8 in bank 354 to close and an impulse over channel 364 will cause the relay No. 5 in bank 356 to close."],
    "318": ["Fig. 11", "The first bank of relay switches associated with the stepping switch 310 is indicated at 318."],
    "104": ["Fig. 3", "The first commutator 96 is connected by wire 114 to the counter 104."],
    "310": ["Fig. 11", "In the counter unit are a plurality of stepping switches indicated at 310, 312, 314 and 316."],
    "236": ["Fig. 10", "In the movement of the card through the reader, a second set of brushes is arranged to contact the \"Start speed\" and \"Speed\" columns of the cards and cause a start speed switch 236 in the control circuit affected to index from its \"off\" position where it is in contact with the terminal 238 through a speed relay control 240 which governs the speed of rotation of the particular axis under control."],
    "256": ["Fig. 10", "When the counters in the absolute comparer section 122' agree with the first slow down value in the storage, an impulse is received by a stepping relay 256 through channel 257 causing contactor of speed switch 236 to position to the next branch speed circuit 244 of the speed relay control 240."],
    "122'": ["Figs. 10, 12", "The first bank of brushes engaging the card also senses the punched holes in the \"Slow down,\" \"Stop\" and \"Check\" columns of each of the axes of the machine and through separate channels transmits this information to the absolute storage and comparer 122' and also to the incremental storage and comparer 122\"."],
    "258": ["Fig. 10", "A delay device 258 is incorporated in a channel 260 connecting the several speed circuits 242, 244 and 246 with the absolute comparer 122'. This delay device opens the circuit 257 to the stepping relay 256 for a short period after an impulse is received and speed switch 236 makes one step."],
    "270": ["Fig. 10", "When speed switch 236 is in \"off\" position, a visual indicator 270 will operate if the absolute comparer storage section 122' is conducting and a visual indicator 272 will operate if the incremental comparer section 122\" is operating."],
    "268": ["Fig. 10", "This circuit has an audible or visual indicator 268 therein which operates when the circuit is closed."],
    "280": ["Fig. 10", "This stepping shaft 280 is common to all of the five sequence control switch mechanisms 224 and in each mechanism drives a rotary member 282."],
    "284": ["Fig. 10", "If two impulses are obtained simultaneously in the circuit 276 for the shaft motor 278 from two machine axes reaching their respective \"stop\" positions simultaneously, a unit 284 senses the increased impulse received and closes momentarily a contact and causes the circuit 286 with which it is associated to add an impulse so that the circuit 276 effectively obtains two impulses."],
    "292": ["Fig. 10", "This last circuit functions as a zeroizing circuit and when activated by engagement between the rotary switch member 282 and contact 299, it clears the numbers stored in the absolute comparer 122', clears both the number and counter circuits of the incremental comparer 122\" through channel 298, opens all the contacts of the sequence switch mechanisms 224 through channel 300, actuates device 288 through channel 302 to close circuit 274, and indexes the card reader through channel 304 to cause the reader to sense the next succeeding card representing the next cutting operation of the machine tool."],
    "294": ["Figs. 12, 13", "When the clearing channel 294 receives an impulse the coils 368 in each of the holding relays is momentarily de-energized which causes these relays to open."],
  },
  // Parts that share a passage: the banks of one storage, the counters of one chain, the
  // comparers, the lamps, the zeroizing channels.
  SAME_PASSAGE: { "352": "350", "354": "350", "356": "350", "320": "318", "322": "318", "324": "318",
    "106": "104", "108": "104", "110": "104", "312": "310", "314": "310", "316": "310",
    "122''": "Incremental comparer (122″): conducts when the increment counter (310–316) stands on the check number held in banks 318–324: at the stop it tells that the move was as long as the card says (lamp 272).",
    "290": "292", "298": "292", "300": "292", "302": "292", "304": "292" },

  // [figure, passage] of a numeral (the cabinet's figure and no passage when the patent has none
  // quoted here).
  passage(numeral) {
    const own = this.PASSAGES[numeral] || this.PASSAGES[this.SAME_PASSAGE[numeral]];
    return own || ["Fig. 10", ""];
  },
};
