// flowsurf — turning VTK's error reports into exceptions (private to src/io).
// VTK readers never throw: they report through vtkErrorMacro and return partial or
// empty output. A VtkMessageTrap collects those reports — from observers on the
// objects we create, and, while a VtkMessageTrap::Active scope runs, from the output
// window for objects created inside VTK — so nothing reaches the terminal and the first
// error becomes a FormatError naming the file. The reader process reads on one thread:
// the first scope replaces VTK's output window and silences vtkLogger for the process's
// life; the window hands a message to the innermost scope's trap when it comes from the
// thread that opened it, and drops it otherwise (or with no scope open).
#pragma once

#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <string>
#include <utility>
#include <vector>

class vtkObject;
class vtkCallbackCommand;

namespace flowsurf::io::detail {

class VtkMessageTrap {
public:
    // Routes VTK's global output to `trap` for the scope's lifetime (scopes nest), which
    // starts empty. Wrap every block of VTK calls made for a trap.
    class Active {
    public:
        explicit Active(VtkMessageTrap& trap);
        ~Active();
        Active(const Active&) = delete;
        Active& operator=(const Active&) = delete;

    private:
        VtkMessageTrap* previous_;
    };

    VtkMessageTrap();
    ~VtkMessageTrap();
    VtkMessageTrap(const VtkMessageTrap&) = delete;
    VtkMessageTrap& operator=(const VtkMessageTrap&) = delete;

    // Observes ErrorEvent and WarningEvent of `object` (a reader or filter).
    void watch(vtkObject* object);

    // Throws FormatError("PATH: WHAT: first error") if an error was reported since the
    // last Active scope on this trap opened; otherwise does nothing.
    void throwIfError(const std::string& path, const std::string& what) const;

    bool hasError() const { return !errors_.empty(); }
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Called by the observers and the output window; the text is cleaned first.
    void add(bool error, const char* text);

private:
    std::vector<std::string> errors_, warnings_;
    vtkSmartPointer<vtkCallbackCommand> callback_;
    // Weak: a filter (and the data it holds) must not outlive its use because it is
    // watched; observers are removed here only from objects still alive.
    std::vector<std::pair<vtkWeakPointer<vtkObject>, unsigned long>> observed_;
};

// Our own warnings about what was read (a field kept with NaN on some patches...), each
// message once per process: a series would repeat it for every step. They wait here until
// the reader process sends them with its next reply (the library prints them).
void warnOnce(const std::string& message);
std::vector<std::string> takeWarnings();

}  // namespace flowsurf::io::detail
