// flowsurf — writes the FlowSurf representation's server-manager XML (ParaView 5.11) to
// stdout, one property per row of the option table that ParaView takes (FrontEnd::ParaView,
// declared in the row), named by session::paraviewProperty: "FlowSurf" + the option in
// CamelCase, --filter-length -> FlowSurfFilterLength. Run at configure time.
#include "session/options/options.h"

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

void property(const OptionSpec& s, std::ostream& o) {
    const std::string name = flowsurf::session::paraviewProperty(s), def = flowsurf::session::defaultText(s);
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
        property(s, o);
        names += "            <Property name=\"" + flowsurf::session::paraviewProperty(s) + "\"/>\n";
    }
    o << "    </RepresentationProxy>\n";
    extension("GeometryRepresentation", names, o);
    extension("UnstructuredGridRepresentation", names, o);
    o << "  </ProxyGroup>\n</ServerManagerConfiguration>\n";
    return 0;
}
