# Every public header of taste2bip must compile on its own.
set(TASTE2BIP_PUBLIC_HEADERS
  taste2bip/taste2bip.h
  taste2bip/names.h
  taste2bip/asn1/data_view.h
  taste2bip/interface_view/interface_view.h
  taste2bip/writer/wrappers.h
  taste2bip/sdl/sdl_ast.h
  taste2bip/sdl/sdl_reader.h
  taste2bip/translate/bip_types.h
  taste2bip/translate/signature.h
  taste2bip/translate/sdl_atom.h)
smcbip_header_check(taste2bip_header_check HEADERS ${TASTE2BIP_PUBLIC_HEADERS}
  LIBRARIES taste2bip)
