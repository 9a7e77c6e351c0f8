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
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace flowsurf::io::detail {

namespace {

// The innermost Active scope's trap, and the thread it was opened on.
VtkMessageTrap* gTrap = nullptr;
std::thread::id gTrapThread;

VtkMessageTrap* trapHere() { return gTrap && std::this_thread::get_id() == gTrapThread ? gTrap : nullptr; }

// Messages from objects nobody observes (parsers and helpers created inside VTK readers)
// go to the global output window: to the current trap, or nowhere.
class CapturingOutputWindow : public vtkOutputWindow {
public:
    static CapturingOutputWindow* New();
    vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
    void DisplayText(const char*) override {}
    void DisplayDebugText(const char*) override {}
    void DisplayErrorText(const char* text) override {
        if (VtkMessageTrap* trap = trapHere()) trap->add(true, text);
    }
    void DisplayWarningText(const char* text) override {
        if (VtkMessageTrap* trap = trapHere()) trap->add(false, text);
    }
    void DisplayGenericWarningText(const char* text) override { DisplayWarningText(text); }
};
vtkStandardNewMacro(CapturingOutputWindow);

// The pipeline's "Algorithm X returned failure for request: vtkInformation (...)" only
// says that something failed; the reader's own message, if any, says what.
bool isExecutiveFailure(const std::string& message) {
    return message.rfind("Algorithm ", 0) == 0 &&
           message.find("returned failure for request") != std::string::npos;
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

// "ERROR: In x.cxx, line 12\nvtkXMLPolyDataReader (0x5f..): Cannot read\n\n" -> "Cannot read".
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

}  // namespace

VtkMessageTrap::Active::Active(VtkMessageTrap& trap) : previous_(gTrap) {
    static const bool installed = [] {
        vtkOutputWindow::SetInstance(vtkSmartPointer<CapturingOutputWindow>::New());
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);  // VTK logs unobserved errors there too
        return true;
    }();
    (void)installed;
    gTrap = &trap;
    gTrapThread = std::this_thread::get_id();
    trap.errors_.clear();
    trap.warnings_.clear();
}

VtkMessageTrap::Active::~Active() { gTrap = previous_; }

VtkMessageTrap::VtkMessageTrap() {
    callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
    callback_->SetCallback([](vtkObject*, unsigned long eventId, void* trap, void* text) {
        static_cast<VtkMessageTrap*>(trap)->add(eventId == vtkCommand::ErrorEvent, static_cast<const char*>(text));
    });
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

void VtkMessageTrap::add(bool error, const char* text) {
    const std::string s = cleanVtkMessage(text);
    if (error) errors_.push_back(s.empty() ? std::string("unspecified VTK error") : s);
    else if (signalsBadData(s)) errors_.push_back(s);
    else if (!s.empty()) warnings_.push_back(s);
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
