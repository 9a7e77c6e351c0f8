// flowsurf — writes the plugin's server-manager XML (ParaView 5.11) to stdout, generated
// from the option table at configure time, as two documents separated by kSplit:
//  1. the FlowSurf representation: one property per row that ParaView takes
//     (FrontEnd::ParaView, declared in the row), named by session::paraviewProperty:
//     "FlowSurf" + the option in CamelCase, --filter-length -> FlowSurfFilterLength;
//  2. the FlowSurf Topology filter: the rows of kTopologyFilterRows (the analysis, not its
//     drawing), named by the option in CamelCase without "topology-" (--topology-scale ->
//     Scale). A row missing from the table fails the configure step.
#include "session/options/options.h"

#include <cctype>
#include <climits>
#include <iostream>
#include <string>

using flowsurf::session::OptionKind;
using flowsurf::session::OptionSpec;

namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

// Separates the representation's document from the filter's.
constexpr const char* kSplit = "<!-- FlowSurfTopology.xml -->";

// The rows the FlowSurf Topology filter takes: what is analysed, not how it is drawn.
constexpr const char* kTopologyFilterRows[] = {"reverse-field",          "topology-parts",
                                               "topology-scale",         "topology-cancel-speed",
                                               "topology-line-strength", "topology-line-length"};

// --topology-cancel-speed -> CancelSpeed.
std::string filterProperty(const OptionSpec& s) {
    std::string name = s.name.rfind("topology-", 0) == 0 ? s.name.substr(9) : s.name, out;
    bool up = true;
    for (char c : name) {
        if (c == '-') {
            up = true;
            continue;
        }
        out += up ? char(std::toupper((unsigned char)c)) : c;
        up = false;
    }
    return out;
}

// One property calling the SetFlowSurfOption* setter of its kind with the option's name.
void property(const OptionSpec& s, const std::string& name, std::ostream& o) {
    const std::string def = flowsurf::session::defaultText(s);
    const std::string doc = "      <Documentation>" + escape(s.help) + " (--" + s.name + ", default " +
                            escape(def) + ")</Documentation>\n";
    auto head = [&](const char* type, const char* command, const std::string& value) {
        o << "      <" << type << " name=\"" << name << "\" command=\"" << command << "\" initial_string=\""
          << s.name << "\" number_of_elements=\"1\" default_values=\"" << escape(value) << "\">\n";
    };
    switch (s.kind) {
    case OptionKind::Flag:
        head("IntVectorProperty", "SetFlowSurfOptionInt", def == "true" ? "1" : "0");
        o << "        <BooleanDomain name=\"bool\"/>\n" << doc << "      </IntVectorProperty>\n";
        break;
    case OptionKind::Int:
        head("IntVectorProperty", "SetFlowSurfOptionInt", def);
        o << "        <IntRangeDomain name=\"range\" min=\"" << (long long)s.min << "\" max=\""
          << (long long)std::min(s.max, double(INT_MAX)) << "\"/>\n"
          << doc << "      </IntVectorProperty>\n";
        break;
    case OptionKind::Float:
        head("DoubleVectorProperty", "SetFlowSurfOptionDouble", def);
        o << "        <DoubleRangeDomain name=\"range\" min=\"" << s.min << "\" max=\"" << s.max << "\"/>\n"
          << doc << "      </DoubleVectorProperty>\n";
        break;
    case OptionKind::Choice:
        head("StringVectorProperty", "SetFlowSurfOptionText", def);
        o << "        <StringListDomain name=\"list\">\n";
        for (const auto& c : s.choices) o << "          <String value=\"" << escape(c) << "\"/>\n";
        o << "        </StringListDomain>\n" << doc << "      </StringVectorProperty>\n";
        break;
    default:
        head("StringVectorProperty", "SetFlowSurfOptionText", def);
        o << doc << "      </StringVectorProperty>\n";
    }
}

void extension(const char* base, const std::string& names, std::ostream& o) {
    o << "    <Extension name=\"" << base << "\">\n"
      << "      <RepresentationType subproxy=\"FlowSurfRepresentation\" text=\"FlowSurf\" subtype=\"Surface\"/>\n"
      << "      <SubProxy>\n"
      << "        <Proxy name=\"FlowSurfRepresentation\" proxygroup=\"representations\" proxyname=\"FlowSurfRepresentation\"/>\n"
      << "        <ShareProperties subproxy=\"SurfaceRepresentation\">\n"
      << "          <Exception name=\"Input\"/>\n          <Exception name=\"Visibility\"/>\n"
      << "        </ShareProperties>\n"
      << "        <ExposedProperties>\n          <PropertyGroup label=\"FlowSurf\">\n" << names
      << "          </PropertyGroup>\n        </ExposedProperties>\n"
      << "      </SubProxy>\n    </Extension>\n";
}

}  // namespace

// The FlowSurf Topology filter (vtkFlowSurfTopologyFilter): any surface with a point vector
// array in, its critical points and separation/attachment lines out.
bool topologyFilter(std::ostream& o) {
    o << "<ServerManagerConfiguration>\n  <ProxyGroup name=\"filters\">\n"
      << "    <SourceProxy name=\"FlowSurfTopology\" class=\"vtkFlowSurfTopologyFilter\" label=\"FlowSurf Topology\">\n"
      << "      <Documentation short_help=\"Critical points and separation/attachment lines of a surface vector field\">"
         "The flow topology of a point vector array on a surface (docs/topology.md): its critical points as vertices "
         "(point arrays type, type_name, index) and its separation and attachment lines as polylines (cell arrays "
         "kind, kind_name; point array strength), in the input's coordinates. Under MPI the pieces are gathered and "
         "the whole result is on process 0. Generated from src/session/options by "
         "src/paraview/representation/generate_xml.cpp.</Documentation>\n"
      << "      <InputProperty name=\"Input\" command=\"SetInputConnection\">\n"
      << "        <ProxyGroupDomain name=\"groups\"><Group name=\"sources\"/><Group name=\"filters\"/></ProxyGroupDomain>\n"
      << "        <DataTypeDomain name=\"input_type\"><DataType value=\"vtkDataSet\"/>"
         "<DataType value=\"vtkCompositeDataSet\"/></DataTypeDomain>\n"
      << "        <InputArrayDomain name=\"input_array\" attribute_type=\"point\" number_of_components=\"3\"/>\n"
      << "        <Documentation>A surface (polygons; other data sets through their outer surface) with a point "
         "vector array.</Documentation>\n"
      << "      </InputProperty>\n"
      << "      <StringVectorProperty name=\"Vectors\" command=\"SetInputArrayToProcess\" number_of_elements=\"5\"\n"
      << "        element_types=\"0 0 0 0 2\" label=\"Vectors\">\n"
      << "        <ArrayListDomain name=\"array_list\" attribute_type=\"Vectors\" input_domain_name=\"input_array\">\n"
      << "          <RequiredProperties><Property name=\"Input\" function=\"Input\"/></RequiredProperties>\n"
      << "        </ArrayListDomain>\n"
      << "        <Documentation>Point array of 3-component vectors to analyse (--field).</Documentation>\n"
      << "      </StringVectorProperty>\n";
    for (const char* row : kTopologyFilterRows) {
        const OptionSpec* s = flowsurf::session::findOption(row);
        if (!s) {
            std::cerr << "generate_xml: the FlowSurf Topology filter's row --" << row << " is not in the table\n";
            return false;
        }
        property(*s, filterProperty(*s), o);
    }
    o << "      <Hints><ShowInMenu category=\"FlowSurf\"/></Hints>\n"
      << "    </SourceProxy>\n  </ProxyGroup>\n</ServerManagerConfiguration>\n";
    return true;
}

int main() {
    std::ostream& o = std::cout;
    std::string names = "            <Property name=\"FlowSurfVectors\"/>\n";
    o << "<ServerManagerConfiguration>\n  <ProxyGroup name=\"representations\">\n"
      << "    <RepresentationProxy name=\"FlowSurfRepresentation\" class=\"vtkFlowSurfRepresentation\"\n"
      << "      processes=\"client|renderserver|dataserver\" base_proxygroup=\"representations\"\n"
      << "      base_proxyname=\"SurfaceRepresentation\">\n"
      << "      <Documentation>flowsurf's ISA, IBFVS and hybrid LIC over ParaView's surface colouring. Generated from "
         "src/session/options/options.cpp by src/paraview/representation/generate_xml.cpp.</Documentation>\n"
      << "      <StringVectorProperty name=\"FlowSurfVectors\" command=\"SetFlowSurfVectors\" number_of_elements=\"5\"\n"
      << "        element_types=\"0 0 0 0 2\" label=\"FlowSurf Vectors\">\n"
      << "        <ArrayListDomain name=\"array_list\" attribute_type=\"Vectors\" input_domain_name=\"input_array_point_3\">\n"
      << "          <RequiredProperties><Property name=\"Input\" function=\"Input\"/></RequiredProperties>\n"
      << "        </ArrayListDomain>\n"
      << "        <Documentation>Point array of 3-component vectors to show (--field).</Documentation>\n"
      << "      </StringVectorProperty>\n";
    for (const OptionSpec& s : flowsurf::session::renderOptionTable()) {
        if (!s.takes(flowsurf::session::FrontEnd::ParaView)) continue;
        property(s, flowsurf::session::paraviewProperty(s), o);
        names += "            <Property name=\"" + flowsurf::session::paraviewProperty(s) + "\"/>\n";
    }
    o << "    </RepresentationProxy>\n";
    extension("GeometryRepresentation", names, o);
    extension("UnstructuredGridRepresentation", names, o);
    o << "  </ProxyGroup>\n</ServerManagerConfiguration>\n" << kSplit << "\n";
    return topologyFilter(o) ? 0 : 1;
}
