#include "io/reader/vtk_messages.h"

#include "core/errors.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <algorithm>
#include <iterator>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

namespace flowsurf::io::detail {

namespace {

// Traps with an Active scope on this thread; the last one collects. A stack rather
// than a pointer, so scopes of different traps may end in any order.
thread_local std::vector<VtkMessageTrap*> tActive;

VtkMessageTrap* currentTrap() { return tActive.empty() ? nullptr : tActive.back(); }

// Messages from objects nobody observes (parsers and helpers created inside VTK
// readers) go to the global output window: route them to this thread's trap, and
// forward anything from threads without a trap to the window we replaced.
class CapturingOutputWindow : public vtkOutputWindow {
public:
    static CapturingOutputWindow* New();
    vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);

    void DisplayText(const char* text) override { forward(text, &vtkOutputWindow::DisplayText); }
    void DisplayErrorText(const char* text) override {
        if (VtkMessageTrap* trap = currentTrap()) trap->addError(text);
        else forward(text, &vtkOutputWindow::DisplayErrorText);
    }
    void DisplayWarningText(const char* text) override {
        if (VtkMessageTrap* trap = currentTrap()) trap->addWarning(text);
        else forward(text, &vtkOutputWindow::DisplayWarningText);
    }
    void DisplayGenericWarningText(const char* text) override {
        if (VtkMessageTrap* trap = currentTrap()) trap->addWarning(text);
        else forward(text, &vtkOutputWindow::DisplayGenericWarningText);
    }
    void DisplayDebugText(const char* text) override {
        forward(text, &vtkOutputWindow::DisplayDebugText);
    }

    vtkSmartPointer<vtkOutputWindow> previous;

private:
    void forward(const char* text, void (vtkOutputWindow::*display)(const char*)) {
        if (!currentTrap() && previous) (previous.Get()->*display)(text);
    }
};
vtkStandardNewMacro(CapturingOutputWindow);

// The capturing window is installed while at least one Active scope runs (any thread).
// VTK also logs every unobserved error through vtkLogger, which prints to stderr on its
// own; its stderr verbosity is lowered for the same period. vtkLogger has no getter
// for it: the cutoff over all outputs is restored, capped at the default (INFO) so a
// verbose log file elsewhere never makes the terminal noisier than before.
std::mutex gWindowMutex;
int gActiveScopes = 0;
vtkSmartPointer<CapturingOutputWindow> gWindow;
vtkLogger::Verbosity gPreviousStderrVerbosity = vtkLogger::VERBOSITY_INFO;

// The pipeline's "Algorithm X returned failure for request: vtkInformation (...)" only
// says that something failed; the reader's own message, if any, says what.
bool isExecutiveFailure(const std::string& message) {
    return message.rfind("Algorithm ", 0) == 0 &&
           message.find("returned failure for request") != std::string::npos;
}

void onVtkEvent(vtkObject*, unsigned long eventId, void* clientData, void* callData) {
    auto* trap = static_cast<VtkMessageTrap*>(clientData);
    const char* text = static_cast<const char*>(callData);
    if (eventId == vtkCommand::ErrorEvent) trap->addError(text);
    else trap->addWarning(text);
}

std::string trim(const std::string& s) {
    const char* ws = " \t\r\n";
    size_t b = s.find_first_not_of(ws);
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

// Messages can quote the file's bytes ("Unrecognized file type: <binary>"): keep
// valid UTF-8, replace other bytes and control characters, and keep it short.
std::string printable(const std::string& s, size_t maxLength = 300) {
    std::string out;
    for (size_t i = 0; i < s.size() && out.size() < maxLength;) {
        unsigned char c = static_cast<unsigned char>(s[i]);
        size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        bool valid = n > 0 && i + n <= s.size();
        for (size_t k = 1; valid && k < n; ++k) valid = (static_cast<unsigned char>(s[i + k]) >> 6) == 0x2;
        if (!valid || (n == 1 && (c < 0x20 || c == 0x7F))) {
            out += c == '\n' || c == '\t' ? ' ' : '?';
            ++i;
        } else {
            out.append(s, i, n);
            i += n;
        }
    }
    if (out.size() >= maxLength) out += "...";
    return out;
}

// Some readers report unreadable data only as a warning and return what they got:
// the legacy reader's "Error reading ascii data. Possible mismatch of datasize with
// declaration." for a truncated file, for instance. These count as errors.
bool signalsBadData(const std::string& message) {
    std::string m = message;
    std::transform(m.begin(), m.end(), m.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* key : {"error reading", "premature", "unexpected end", "truncat",
                            "mismatch of datasize", "end of file"})
        if (m.find(key) != std::string::npos) return true;
    return false;
}

}  // namespace

std::string cleanVtkMessage(const char* text) {
    std::string s = text ? text : "";
    // Drop the "ERROR: In FILE, line N" (or "Warning: In ...") source location line.
    if ((s.rfind("ERROR: In ", 0) == 0 || s.rfind("Warning: In ", 0) == 0 ||
         s.rfind("Generic Warning: In ", 0) == 0)) {
        size_t nl = s.find('\n');
        s = nl == std::string::npos ? std::string() : s.substr(nl + 1);
    }
    // Drop the "vtkClassName (0x55d1c0): " object prefix; the user knows no class names.
    if (s.rfind("vtk", 0) == 0) {
        size_t p = s.find(" (0x");
        size_t q = s.find("): ");
        if (p != std::string::npos && q != std::string::npos && p < q &&
            s.find_first_of(" \n") == p)
            s = s.substr(q + 3);
    }
    return printable(trim(s));
}

VtkMessageTrap::Active::Active(VtkMessageTrap& trap) : trap_(&trap) {
    tActive.push_back(trap_);
    std::lock_guard<std::mutex> lock(gWindowMutex);
    if (gActiveScopes++ == 0) {
        gWindow = vtkSmartPointer<CapturingOutputWindow>::New();
        gWindow->previous = vtkOutputWindow::GetInstance();
        vtkOutputWindow::SetInstance(gWindow);
        gPreviousStderrVerbosity =
            std::min(vtkLogger::GetCurrentVerbosityCutoff(), vtkLogger::VERBOSITY_INFO);
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
}

VtkMessageTrap::Active::~Active() {
    // The most recent entry for this trap (scopes of one trap nest on a thread).
    auto it = std::find(tActive.rbegin(), tActive.rend(), trap_);
    if (it != tActive.rend()) tActive.erase(std::next(it).base());
    std::lock_guard<std::mutex> lock(gWindowMutex);
    if (--gActiveScopes == 0) {
        vtkOutputWindow::SetInstance(gWindow->previous);
        gWindow = nullptr;
        vtkLogger::SetStderrVerbosity(gPreviousStderrVerbosity);
    }
}

VtkMessageTrap::VtkMessageTrap() {
    callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
    callback_->SetCallback(onVtkEvent);
    callback_->SetClientData(this);
}

VtkMessageTrap::~VtkMessageTrap() {
    for (auto& [object, tag] : observed_)
        if (object) object->RemoveObserver(tag);
}

void VtkMessageTrap::watch(vtkObject* object) {
    if (!object) return;
    unsigned long errorTag = object->AddObserver(vtkCommand::ErrorEvent, callback_);
    unsigned long warningTag = object->AddObserver(vtkCommand::WarningEvent, callback_);
    observed_.emplace_back(object, errorTag);
    observed_.emplace_back(object, warningTag);
    // The executive reports a failed request of its algorithm.
    if (auto* algorithm = vtkAlgorithm::SafeDownCast(object)) watch(algorithm->GetExecutive());
}

void VtkMessageTrap::addError(const char* text) {
    std::string s = cleanVtkMessage(text);
    errors_.push_back(s.empty() ? std::string("unspecified VTK error") : s);
}

void VtkMessageTrap::addWarning(const char* text) {
    std::string s = cleanVtkMessage(text);
    if (s.empty()) return;
    if (signalsBadData(s)) errors_.push_back(s);
    else warnings_.push_back(s);
}

void VtkMessageTrap::clear() {
    errors_.clear();
    warnings_.clear();
}

void VtkMessageTrap::throwIfError(const std::string& path, const std::string& what) const {
    if (errors_.empty()) return;
    std::string reason;
    for (const auto& e : errors_)
        if (!isExecutiveFailure(e)) {
            reason = e;
            break;
        }
    if (reason.empty()) reason = warnings_.empty() ? "the reader failed without saying why" : warnings_.front();
    throw FormatError(path + ": " + what + ": " + reason);
}

namespace {
std::mutex warningLock;
std::set<std::string> warningsSaid;
std::vector<std::string> warningsPending;
}  // namespace

void warnOnce(const std::string& message) {
    std::lock_guard<std::mutex> guard(warningLock);
    if (warningsSaid.insert(message).second) warningsPending.push_back(message);
}

std::vector<std::string> takeWarnings() {
    std::lock_guard<std::mutex> guard(warningLock);
    return std::exchange(warningsPending, {});
}

}  // namespace flowsurf::io::detail
