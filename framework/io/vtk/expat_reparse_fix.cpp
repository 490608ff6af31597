// Makes VTK's XML readers work with Expat 2.6's "reparse deferral", for VTK builds older
// than 9.3 (ParaView 5.11's VTK on Debian 12).
//
// Expat 2.6.0 (and Debian 12's libexpat1 2.5.0-1+deb12u1 and later, which backport it as
// the fix of CVE-2023-52425) may defer reporting an element until more input arrives. VTK's
// XML parser feeds a file in chunks and stops when it has seen <AppendedData>, before the
// raw binary that follows; with deferral it sees the element too late, hands the binary to
// Expat and fails with "not well-formed (invalid token)" (VTK issue 19258; fixed in VTK 9.3,
// and in Debian's libvtk9 9.1.0+really9.1.0+dfsg2-5+deb12u1, by disabling deferral on each
// parser). ParaView 5.11 on Debian 12 was not rebuilt with the fix: its VTK cannot read
// .vtp/.vtu files with appended data. This file applies VTK's fix from outside: it defines
// XML_ParserCreate, which the dynamic linker binds VTK's calls to (libsubdiv_vtkio comes
// before libexpat in the program's search order), creates the parser with Expat's own
// function and turns deferral off. Compiled only for VTK < 9.3 (framework/CMakeLists.txt).
#include <dlfcn.h>

extern "C" {

struct XML_ParserStruct;
using XML_Parser = XML_ParserStruct*;
using XML_Char = char;
using XML_Bool = unsigned char;

XML_Parser XML_ParserCreate(const XML_Char* encoding) {
  using Create = XML_Parser (*)(const XML_Char*);
  using SetDeferral = XML_Bool (*)(XML_Parser, XML_Bool);
  static const auto create = reinterpret_cast<Create>(dlsym(RTLD_NEXT, "XML_ParserCreate"));
  // Absent from Expat before 2.6 (and from unpatched 2.5): nothing to turn off there.
  static const auto set_deferral = reinterpret_cast<SetDeferral>(dlsym(RTLD_NEXT, "XML_SetReparseDeferralEnabled"));
  if (!create) return nullptr;
  XML_Parser parser = create(encoding);
  if (parser && set_deferral) set_deferral(parser, XML_Bool(0));
  return parser;
}

}  // extern "C"
