#pragma once

// A real pseudo-terminal pair for device tests: the device opens the slave side by a stable
// name (a symbolic link in a temporary folder, so "unplugging" and "plugging in" again keeps
// the name), the test plays the instrument on the master side. Header-only (also used by the
// UI tests). Linux/glibc: openpty() from <pty.h>.
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QSocketNotifier>
#include <QString>
#include <QTemporaryDir>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

namespace tt::devices::test {

class PtyPair {
public:
    /// Opens the pair and links <tmp>/<name> to the slave.
    explicit PtyPair(const QString& name = QStringLiteral("ttyTEST")) : m_link(m_dir.filePath(name)) { plug(); }
    ~PtyPair() { unplug(); }
    PtyPair(const PtyPair&) = delete;
    PtyPair& operator=(const PtyPair&) = delete;

    /// The name the device opens (stable across unplug/replug).
    QString portName() const { return m_link; }
    /// The current slave device (/dev/pts/N).
    QString slavePath() const { return m_slavePath; }
    bool plugged() const { return m_master >= 0; }

    /// Called with the bytes the device writes.
    void onBytes(std::function<void(const QByteArray&)> handler) { m_handler = std::move(handler); }

    /// The instrument sends bytes to the device.
    void send(const QByteArray& bytes) {
        if (m_master < 0) return;
        qsizetype done = 0;
        while (done < bytes.size()) {
            const ssize_t n = ::write(m_master, bytes.constData() + done, static_cast<size_t>(bytes.size() - done));
            if (n <= 0) return;
            done += n;
        }
    }
    void send(const std::vector<std::uint8_t>& bytes) {
        send(QByteArray(reinterpret_cast<const char*>(bytes.data()), static_cast<qsizetype>(bytes.size())));
    }

    /// Pulls the cable: closes the master side; the device's reads fail.
    void unplug() {
        m_notifier.reset();
        if (m_master >= 0) ::close(m_master);
        if (m_slaveHold >= 0) ::close(m_slaveHold);
        m_master = -1;
        m_slaveHold = -1;
        // The name leads nowhere until plug(): the closed pseudo-terminal's number may be given to another
        // test's pair meanwhile, and a device reopening the old path would find that one.
        if (!m_link.isEmpty()) QFile::remove(m_link);
    }

    /// Plugs the cable in again: a new pair behind the same name.
    void plug() {
        unplug();
        int slave = -1;
        termios raw{};
        cfmakeraw(&raw);
        char name[128] = {};
        if (::openpty(&m_master, &slave, name, &raw, nullptr) != 0) throw std::runtime_error("openpty failed");
        m_slavePath = QString::fromLocal8Bit(name);
        // Keep a slave descriptor open until the device opens it, so writes before that are kept
        // and the master does not see a hang-up; released by releaseSlave().
        m_slaveHold = slave;
        ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
        const QString tmp = m_link + QStringLiteral(".new");
        QFile::remove(tmp);
        if (!QFile::link(m_slavePath, tmp) || ::rename(tmp.toLocal8Bit().constData(), m_link.toLocal8Bit().constData()))
            throw std::runtime_error("cannot link the pseudo-terminal");
        m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
        QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] { readMaster(); });
    }

    /// Closes the test's own slave descriptor (after the device has opened the port), so that
    /// closing the device is seen like on real hardware.
    void releaseSlave() {
        if (m_slaveHold >= 0) ::close(m_slaveHold);
        m_slaveHold = -1;
    }

private:
    void readMaster() {
        char buffer[4096];
        QByteArray got;
        for (;;) {
            const ssize_t n = ::read(m_master, buffer, sizeof buffer);
            if (n <= 0) break;
            got.append(buffer, n);
        }
        if (!got.isEmpty() && m_handler) m_handler(got);
    }

    QTemporaryDir m_dir;
    QString m_link;
    QString m_slavePath;
    int m_master = -1;
    int m_slaveHold = -1;
    std::unique_ptr<QSocketNotifier> m_notifier;
    std::function<void(const QByteArray&)> m_handler;
};

/// A null-modem cable between two pseudo-terminals (for Modbus RTU: the server on one end, the
/// device on the other), which the test can pull out, or make corrupt the bytes it carries.
class PtyNullModem {
public:
    PtyNullModem() : m_a(QStringLiteral("ttyA")), m_b(QStringLiteral("ttyB")) {
        m_a.onBytes([this](const QByteArray& bytes) { carry(bytes, m_b, m_corruptAtoB); });
        m_b.onBytes([this](const QByteArray& bytes) { carry(bytes, m_a, m_corruptBtoA); });
    }
    QString endA() const { return m_a.portName(); }
    QString endB() const { return m_b.portName(); }
    /// Stops carrying bytes (the cable is cut) or carries them again.
    void setCut(bool cut) { m_cut = cut; }
    /// Flips a bit in every byte travelling from B to A (or A to B) while on.
    void setCorruptBtoA(bool on) { m_corruptBtoA = on; }
    void setCorruptAtoB(bool on) { m_corruptAtoB = on; }
    std::uint64_t bytesCarried() const { return m_carried; }

private:
    void carry(QByteArray bytes, PtyPair& to, bool corrupt) {
        if (m_cut) return;
        if (corrupt && !bytes.isEmpty()) bytes[bytes.size() - 1] = static_cast<char>(bytes[bytes.size() - 1] ^ 0x01);
        m_carried += static_cast<std::uint64_t>(bytes.size());
        to.send(bytes);
    }

    PtyPair m_a;
    PtyPair m_b;
    bool m_cut = false;
    bool m_corruptBtoA = false;
    bool m_corruptAtoB = false;
    std::uint64_t m_carried = 0;
};

}  // namespace tt::devices::test
