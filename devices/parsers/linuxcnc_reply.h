#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "devices/parsers/parse_result.h"

/// The replies of LinuxCNC's remote shell (linuxcncrsh, `man linuxcncrsh`), as the Debian 12 package
/// (2.9.0~pre1) writes them: framing, the reply to each request, and the typed values TrueTurn reads.
/// Pure functions; the TCP client that sends the requests lives in devices/linuxcnc. Every refusal means
/// the stream is out of step or corrupt: the caller resets the connection.
namespace tt::devices::linuxcnc {

/// Longest reply line accepted, characters (an operator message is at most 255 characters plus its key).
inline constexpr std::size_t kMaxReplyLength = 512;

/// Splits the shell's byte stream into reply lines. Any run of CR and LF ends a line (values end with
/// CR LF, acknowledgements with LF CR, help texts with LF CR between lines); empty lines are skipped. A line
/// longer than the limit or a byte outside printable ASCII makes the stream corrupt: corrupt() becomes
/// true and stays so until reset() (the connection must be reset, the replies are out of step).
class ReplyFramer {
public:
    /// `maxLength`: longest accepted line without its terminator (> 0).
    explicit ReplyFramer(std::size_t maxLength = kMaxReplyLength);
    /// Appends bytes and returns every line they complete, oldest first (none once corrupt).
    std::vector<std::string> feed(std::string_view bytes);
    /// A line was too long or held a byte that is not printable ASCII.
    bool corrupt() const { return m_corrupt; }
    /// Why the stream is corrupt, in the user's terms; empty when it is not.
    const std::string& problem() const { return m_problem; }
    /// Characters of a line still waiting for its end (a reply cut off when the connection ends).
    std::size_t pending() const { return m_buffer.size(); }
    /// Forgets everything (after a reconnect).
    void reset();

private:
    std::size_t m_maxLength;
    std::string m_buffer;
    bool m_corrupt = false;
    std::string m_problem;
};

/// What kind of reply a line is.
enum class ReplyKind {
    HelloAck,  ///< HELLO ACK <server> <version>: the connect password was right
    HelloNak,  ///< HELLO NAK: wrong password or a malformed hello
    Ack,       ///< SET <COMMAND> ACK (verbose mode): the set command was carried out
    Nak,       ///< SET <COMMAND> NAK or GET <COMMAND> NAK: refused or failed
    Value,     ///< <KEY> <value words>: the answer to a get
};

/// One reply line, split.
struct Reply {
    ReplyKind kind = ReplyKind::Value;
    std::string key;                 ///< the sub-command in upper case ("ESTOP", "MDI"); "HELLO" for hello replies
    std::vector<std::string> words;  ///< the words after the key (a value's words; server and version of a hello)
    std::string text;                ///< everything after the key and one space, as sent (messages)
};

/// Splits one reply line: `HELLO ACK <server> <version>`, `HELLO NAK`, `SET <CMD> ACK|NAK`, `GET <CMD> NAK`
/// or `<KEY> <value...>` (KEY: upper-case letters, digits and '_'). Refuses an empty line, a bad key or
/// an acknowledgement that is not one of these forms.
ParseResult<Reply> parseReply(std::string_view line);

/// The reply `line` as the answer to `request` (as sent: "get estop", "set mdi G21", "hello EMC tt 1.0"):
/// a hello gets HELLO ACK/NAK; `set X ...` gets SET X ACK or NAK; `get X` gets X <value> or GET X NAK
/// (the shell answers `get program_linear_units` with PROGRAM_UNITS and `get timeout` with SET_TIMEOUT).
/// A reply that answers another request (the stream is out of step) or is garbage is refused.
ParseResult<Reply> replyTo(std::string_view request, std::string_view line);

/// The task's mode.
enum class TaskMode { Manual, Auto, Mdi };
/// The interpreter's state.
enum class ProgramStatus { Idle, Running, Paused };
/// The machine's linear units (user units of the trajectory planner).
enum class LinearUnits { Inch, Millimetre, Centimetre, Custom };

/// ON / OFF of ESTOP, MACHINE, ... (true = ON). Refuses another key than `key` or another word.
ParseResult<bool> onOff(const Reply& reply, std::string_view key);
/// MODE MANUAL|AUTO|MDI.
ParseResult<TaskMode> taskMode(const Reply& reply);
/// PROGRAM_STATUS IDLE|RUNNING|PAUSED.
ParseResult<ProgramStatus> programStatus(const Reply& reply);
/// JOINT_HOMED YES|NO ... (the manual's HOMED|NOT also accepted), one per joint.
ParseResult<std::vector<bool>> jointsHomed(const Reply& reply);
/// A position reply of `key` (ABS_ACT_POS, ABS_CMD_POS, REL_ACT_POS): six finite numbers X Y Z A B C, in the
/// machine's linear units.
ParseResult<std::array<double, 6>> position(const Reply& reply, std::string_view key);
/// USER_LINEAR_UNITS (or PROGRAM_UNITS, DISPLAY_LINEAR_UNITS) INCH|MM|CM|CUSTOM (|NONE refused).
ParseResult<LinearUnits> linearUnits(const Reply& reply, std::string_view key);
/// A whole number after `key` (PROGRAM_LINE, TOOL).
ParseResult<std::int64_t> integerValue(const Reply& reply, std::string_view key);
/// The message of ERROR / OPERATOR_DISPLAY / OPERATOR_TEXT; empty when the shell says OK (no message).
ParseResult<std::string> message(const Reply& reply, std::string_view key);

/// The numbers of an operator message written by `(DEBUG,<tag> #a #b ...)`: the text must start with `tag`
/// followed by exactly `count` finite numbers (LinuxCNC prints each with six decimals).
ParseResult<std::vector<double>> taggedNumbers(std::string_view text, std::string_view tag, std::size_t count);

/// A decimal number as LinuxCNC prints it ("-0.012300", "5.000000"): the whole word, finite.
ParseResult<double> number(std::string_view word);

/// Plain English name of a mode / status / units, for messages ("MDI", "running", "inch").
std::string_view modeName(TaskMode mode);
std::string_view statusName(ProgramStatus status);
std::string_view unitsName(LinearUnits units);
/// Millimetres per machine unit; 0 for custom units (positions cannot be converted).
double millimetresPer(LinearUnits units);

}  // namespace tt::devices::linuxcnc
